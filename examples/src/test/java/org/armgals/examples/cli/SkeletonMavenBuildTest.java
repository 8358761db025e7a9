package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.xpath.XPathFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A skeleton of {@code armgals new} builds, passes its tests and runs with Maven, as its README
 * says: {@code ./mvnw verify exec:java}, through its own Maven wrapper, on this JDK; and {@code
 * exec:exec} runs it with its meta level in a JVM of its own, the same run.
 *
 * <p>Which Maven build: a real one, offline. The armgals artifacts it depends on are not in the
 * local repository (this build never installs them), so the test stages them in a repository of its
 * own, from this build's {@code target/classes} and POMs, and gives Maven the build's local
 * repository (for the plugins, JUnit and the third-party jars) as a read-only tail ({@code
 * maven.repo.local.tail}, Maven 3.9): nothing is written there. It takes 30 to 60 s.
 */
class SkeletonMavenBuildTest {
  private static final Path CHECKOUT = Path.of("").toAbsolutePath().getParent();

  @TempDir Path dir;

  @Test
  void theSkeletonBuildsPassesItsTestsAndRunsWithItsMavenWrapperOfflineItsMetaLocalOrRemote()
      throws Exception {
    String version = NewCommand.version();
    Path repository = dir.resolve("repository");
    stage(repository, version);
    Path project = dir.resolve("mybot");
    NewCommand.write("mybot", project, version);
    Path local = Path.of(System.getProperty("armgals.localRepository", "(unset)"));
    assertThat(local).as("the build's local repository").isDirectory();

    String out =
        maven(
            project,
            repository,
            local,
            "-Dexec.args=run mybot --cycles 100 --out runs/mybot",
            "verify",
            "exec:java");
    assertThat(out)
        .as(out)
        .contains("Tests run: 2, Failures: 0, Errors: 0, Skipped: 0")
        .contains("summary of mybot:")
        .containsPattern("robot cycles +100")
        .contains("local, in the robots' JVM");
    assertThat(project.resolve("runs/mybot/trace.jsonl")).isNotEmptyFile();

    // As its README says: the meta level in a JVM of its own needs the robot's in one of its own.
    String remote =
        maven(
            project,
            repository,
            local,
            "-Dexec.args=-cp %classpath mybot.MybotExample run mybot --cycles 100 --meta remote"
                + " --out runs/remote",
            "exec:exec");
    assertThat(remote)
        .as(remote)
        .contains("remote, in a JVM of its own over the broker")
        .containsPattern("robot cycles +100");
    assertThat(project.resolve("runs/remote/loop.jsonl"))
        .hasSameTextualContentAs(project.resolve("runs/mybot/loop.jsonl"));
    assertThat(repository.resolve("org/junit")).doesNotExist(); // the tail was only read
  }

  /** Runs the skeleton's Maven wrapper offline with {@code arguments}; answers what it printed. */
  private static String maven(Path project, Path repository, Path local, String... arguments)
      throws Exception {
    List<String> command =
        new java.util.ArrayList<>(
            List.of(
                project.resolve("mvnw").toString(),
                "-B",
                "-o",
                "-Dmaven.repo.local=" + repository,
                "-Dmaven.repo.local.tail=" + local));
    command.addAll(List.of(arguments));
    ProcessBuilder builder =
        new ProcessBuilder(command).directory(project.toFile()).redirectErrorStream(true);
    builder.environment().put("JAVA_HOME", System.getProperty("java.home"));
    builder.environment().remove("MAVEN_OPTS");
    builder.environment().remove("MAVEN_ARGS");
    Process maven = builder.start();
    String out = new String(maven.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
    assertThat(maven.waitFor(5, TimeUnit.MINUTES)).isTrue();
    assertThat(maven.exitValue()).as(out).isZero();
    return out;
  }

  /**
   * Puts armgals' parent POM and each module's POM and jar (of its {@code target/classes}) into
   * {@code repository}, as {@code install} would.
   */
  private static void stage(Path repository, String version) throws Exception {
    place(repository, "armgals-parent", version, "pom", CHECKOUT.resolve("pom.xml"));
    for (String module : modules()) {
      Path classes = CHECKOUT.resolve(module).resolve("target/classes");
      if (!Files.isDirectory(classes)) {
        continue; // not built by this build: examples does not depend on it
      }
      Path pom = CHECKOUT.resolve(module).resolve("pom.xml");
      String artifact =
          XPathFactory.newInstance()
              .newXPath()
              .evaluate(
                  "/project/artifactId",
                  DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(pom.toFile()));
      place(repository, artifact, version, "pom", pom);
      Path jar = Files.createTempFile(repository.getParent(), artifact, ".jar");
      jar(classes, jar);
      place(repository, artifact, version, "jar", jar);
    }
  }

  private static List<String> modules() throws IOException {
    return Files.readAllLines(CHECKOUT.resolve("pom.xml"), StandardCharsets.UTF_8).stream()
        .map(String::strip)
        .filter(l -> l.startsWith("<module>"))
        .map(l -> l.substring("<module>".length(), l.indexOf("</module>")))
        .toList();
  }

  private static void place(
      Path repository, String artifact, String version, String type, Path file) throws IOException {
    Path target =
        repository.resolve(
            "org/armgals/"
                + artifact
                + "/"
                + version
                + "/"
                + artifact
                + "-"
                + version
                + "."
                + type);
    Files.createDirectories(target.getParent());
    Files.copy(file, target);
  }

  private static void jar(Path classes, Path jar) throws IOException {
    try (OutputStream file = Files.newOutputStream(jar);
        JarOutputStream out = new JarOutputStream(file);
        Stream<Path> files = Files.walk(classes)) {
      for (Path path : files.filter(Files::isRegularFile).sorted().toList()) {
        String name = classes.relativize(path).toString().replace('\\', '/');
        out.putNextEntry(new JarEntry(name));
        Files.copy(path, out);
        out.closeEntry();
      }
    }
  }
}
