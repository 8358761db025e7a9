package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.URI;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.jar.JarFile;
import java.util.jar.Manifest;
import java.util.stream.Stream;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.xpath.XPath;
import javax.xml.xpath.XPathConstants;
import javax.xml.xpath.XPathFactory;
import org.armgals.examples.run.Example;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.NodeList;

/** {@code armgals new} writes a robot skeleton that compiles as written, and refuses bad names. */
class NewCommandTest {
  @TempDir Path dir;

  @Test
  void theSkeletonCompilesWithoutAWarning() throws IOException {
    Path target = dir.resolve("mybot");
    List<Path> written = NewCommand.write("mybot", target, "9.9.9-TEST");

    assertThat(written)
        .extracting(p -> target.relativize(p).toString().replace(File.separatorChar, '/'))
        .containsExactly(
            "pom.xml",
            "README.md",
            "src/main/java/mybot/Signals.java",
            "src/main/java/mybot/Modules.java",
            "src/main/java/mybot/MybotRobot.java",
            "src/main/java/mybot/MybotMeta.java",
            "src/main/java/mybot/MybotExample.java",
            "src/main/resources/META-INF/services/org.armgals.examples.sim.SimExample",
            "src/test/java/mybot/MybotRobotTest.java",
            "mvnw",
            "mvnw.cmd",
            ".mvn/wrapper/maven-wrapper.properties");
    String pom = Files.readString(target.resolve("pom.xml"), StandardCharsets.UTF_8);
    assertThat(pom)
        .contains("<armgals.version>9.9.9-TEST</armgals.version>")
        .contains("<artifactId>examples</artifactId>")
        .contains("<artifactId>maam-framework</artifactId>")
        .contains("<artifactId>maam-sim</artifactId>")
        .contains("<version>${armgals.version}</version>")
        .contains("<mainClass>mybot.MybotExample</mainClass>");
    for (Path file : written.subList(0, 9)) {
      assertThat(Files.readString(file, StandardCharsets.UTF_8))
          .as("%s has no placeholder left but Maven's", file)
          .doesNotContainPattern("\\$\\{(name|Name|package|version)}")
          .doesNotContain("// tag::");
    }

    assertThat(compile(written.stream().filter(p -> p.toString().endsWith(".java")).toList()))
        .isEmpty();
    assertThat(dir.resolve("classes/mybot/MybotExample.class")).exists();
    assertThat(dir.resolve("classes/mybot/MybotRobotTest.class")).exists();
    assertThat(runBriefly()).contains(new Summary.Entry("robot cycles", "10"));
    assertThat(
            Files.readString(
                target.resolve(
                    "src/main/resources/META-INF/services/org.armgals.examples.sim.SimExample")))
        .contains("\nmybot.MybotExample\n");
  }

  @Test
  void theSkeletonsMetaLevelRunsInAJvmOfItsOwnAndGivesTheSameRunAsInTheRobotsJvm()
      throws Exception {
    Path target = dir.resolve("mybot");
    List<Path> written = NewCommand.write("mybot", target, "9.9.9-TEST");
    assertThat(compile(written.stream().filter(p -> p.toString().endsWith(".java")).toList()))
        .isEmpty();
    Path services = Path.of("META-INF/services/org.armgals.examples.sim.SimExample");
    Files.createDirectories(dir.resolve("classes").resolve(services).getParent());
    Files.copy(
        target.resolve("src/main/resources").resolve(services),
        dir.resolve("classes").resolve(services));
    List<String> run = List.of("run", "mybot", "--cycles", "150", "--out");

    // The robot's JVM is a child too: a meta level's JVM gets its class path, the skeleton's with
    // it.
    Map<String, String> results = new java.util.LinkedHashMap<>();
    for (String place : List.of("local", "remote")) {
      List<String> command = new ArrayList<>();
      command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
      command.addAll(List.of("-cp", dir.resolve("classes") + File.pathSeparator + classPathText()));
      command.add("mybot.MybotExample");
      command.addAll(run);
      command.addAll(List.of(dir.resolve(place).toString(), "--meta", place));
      Process java = new ProcessBuilder(command).redirectErrorStream(true).start();
      String out = new String(java.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
      assertThat(java.waitFor()).as(out).isZero();
      results.put(place, out);
    }

    assertThat(results.get("remote")).contains("remote, in a JVM of its own over the broker");
    assertThat(results.get("local")).contains("local, in the robots' JVM");
    for (String file : List.of("trace.jsonl", "loop.jsonl")) {
      String local = Files.readString(dir.resolve("local").resolve(file), StandardCharsets.UTF_8);
      assertThat(local).as(file).contains("\"cycle\":1");
      assertThat(Files.readString(dir.resolve("remote").resolve(file), StandardCharsets.UTF_8))
          .as(file + ", remote against local")
          .isEqualTo(local);
    }
    assertThat(Files.readString(dir.resolve("local/loop.jsonl"), StandardCharsets.UTF_8))
        .contains("\"event\":\"applied\"");
  }

  @Test
  void theSkeletonHasTheMavenWrapperOfArmgalsExecutable() throws IOException {
    Path target = dir.resolve("mybot");
    NewCommand.write("mybot", target, "9.9.9-TEST");
    Path checkout = Path.of("").toAbsolutePath().getParent();

    for (String file : List.of("mvnw", "mvnw.cmd", ".mvn/wrapper/maven-wrapper.properties")) {
      assertThat(target.resolve(file)).as(file).hasSameBinaryContentAs(checkout.resolve(file));
    }
    assertThat(Files.isExecutable(target.resolve("mvnw"))).isTrue();
  }

  @Test
  void theSkeletonsSourcesAreFormattedAsArmgalsOwnWhateverTheNamesLength() throws Exception {
    List<String> sources = new ArrayList<>();
    for (String name : List.of("bot", "mybot", "abcdefghijklmnopqrst")) {
      NewCommand.write(name, dir.resolve(name), "9.9.9-TEST").stream()
          .filter(p -> p.toString().endsWith(".java"))
          .forEach(p -> sources.add(p.toString()));
    }
    Path formatter = Path.of(System.getProperty("armgals.formatter", "(armgals.formatter unset)"));
    assertThat(formatter).as("google-java-format, as the build fetches it").isRegularFile();

    List<String> command = new ArrayList<>();
    command.addAll(
        List.of(
            Path.of(System.getProperty("java.home"), "bin", "java").toString(),
            "-jar",
            formatter.toString(),
            "--dry-run"));
    command.addAll(sources);
    Process format = new ProcessBuilder(command).redirectErrorStream(true).start();
    String unformatted = new String(format.getInputStream().readAllBytes(), StandardCharsets.UTF_8);

    assertThat(format.waitFor()).as(unformatted).isZero();
    assertThat(unformatted).as("the files google-java-format would change").isEmpty();
  }

  /** Runs the compiled skeleton's example for ten cycles; answers its summary. */
  private List<Summary.Entry> runBriefly() throws IOException {
    try (URLClassLoader loader =
        new URLClassLoader(
            new URL[] {dir.resolve("classes").toUri().toURL()}, getClass().getClassLoader())) {
      Example example =
          (Example) loader.loadClass("mybot.MybotExample").getDeclaredConstructor().newInstance();
      RunSettings settings =
          new RunSettings(
              OptionalLong.of(10),
              Optional.empty(),
              Duration.ofMillis(10),
              1,
              Optional.empty(),
              false,
              Optional.empty(),
              dir.resolve("run"));
      return example.run(settings, new PrintStream(OutputStream.nullOutputStream())).entries();
    } catch (ReflectiveOperationException e) {
      throw new AssertionError("the skeleton's example cannot be made", e);
    }
  }

  @Test
  void theSkeletonsPomParsesAndPinsTheReleaseAndTheRequirements() throws Exception {
    Path target = dir.resolve("mybot");
    NewCommand.write("mybot", target, "9.9.9-TEST");

    DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
    factory.setNamespaceAware(false);
    factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
    Document pom = factory.newDocumentBuilder().parse(target.resolve("pom.xml").toFile());
    XPath xpath = XPathFactory.newInstance().newXPath();

    assertThat(xpath.evaluate("/project/properties/maven.compiler.release", pom)).isEqualTo("21");
    assertThat(xpath.evaluate("/project/artifactId", pom)).isEqualTo("mybot");
    String enforcer = "//plugin[artifactId='maven-enforcer-plugin']";
    assertThat(xpath.evaluate(enforcer + "//requireMavenVersion/version", pom)).isEqualTo("[3.9,)");
    assertThat(xpath.evaluate(enforcer + "//requireJavaVersion/version", pom)).isEqualTo("[21,)");
    assertThat(xpath.evaluate(enforcer + "//requireJavaVersion/message", pom))
        .contains("JDK 21 or later");
    NodeList plugins = (NodeList) xpath.evaluate("//plugin", pom, XPathConstants.NODESET);
    for (int i = 0; i < plugins.getLength(); i++) {
      assertThat(xpath.evaluate("version", plugins.item(i)))
          .as("the version of %s", xpath.evaluate("artifactId", plugins.item(i)))
          .matches("\\d+(\\.\\d+)+");
    }
    assertThat(xpath.evaluate("//plugin[artifactId='maven-compiler-plugin']/version", pom))
        .isNotEmpty();
  }

  @Test
  void theVersionIsTheBuildsOwn() {
    assertThat(NewCommand.version()).matches("\\d+\\.\\d+\\.\\d+.*");
  }

  @Test
  void badNamesAndExistingDirectoriesAreRefusedWritingNothing() throws IOException {
    for (String bad : List.of("MyBot", "my-bot", "9bot", "", "class", "abcdefghijklmnopqrstu")) {
      assertThatThrownBy(() -> NewCommand.write(bad, dir.resolve("x"), "1"))
          .as(bad)
          .isInstanceOf(UsageException.class)
          .hasMessageContaining("'" + bad + "'");
    }
    Path existing = Files.createDirectory(dir.resolve("taken"));
    assertThatThrownBy(() -> NewCommand.write("taken", existing, "1"))
        .isInstanceOf(UsageException.class)
        .hasMessageContaining("already exists");
    assertThat(dir.resolve("x")).doesNotExist();
    try (Stream<Path> files = Files.list(existing)) {
      assertThat(files).isEmpty();
    }
  }

  @Test
  void aSkeletonInsideAnArmgalsCheckoutIsRefusedWritingNothing() throws IOException {
    Path checkout = Files.createDirectories(dir.resolve("armgals"));
    Files.writeString(
        checkout.resolve("pom.xml"),
        "<project>\n  <groupId>org.armgals</groupId>\n"
            + "  <artifactId>armgals-parent</artifactId>\n</project>\n");
    Path deeper = Files.createDirectories(checkout.resolve("examples/src"));

    for (Path target : List.of(checkout.resolve("mybot"), deeper.resolve("mybot"))) {
      assertThatThrownBy(() -> NewCommand.write("mybot", target, "1"))
          .as(target.toString())
          .isInstanceOf(UsageException.class)
          .hasMessage(
              target
                  + " is inside the armgals checkout "
                  + checkout
                  + ", whose build would take it for one of its own; write it elsewhere, say"
                  + " --dir "
                  + dir.resolve("mybot"));
      assertThat(target).doesNotExist();
    }
    assertThat(NewCommand.write("mybot", dir.resolve("mybot"), "1")).isNotEmpty();
  }

  @Test
  void placeholdersMavenOwnsAreLeftAlone() {
    assertThat(NewCommand.fill("${name}: ${project.version} ${other}", Map.of("name", "bot")))
        .isEqualTo("bot: ${project.version} ${other}");
  }

  /** Compiles {@code sources} against the test's class path; answers the diagnostics. */
  private List<String> compile(List<Path> sources) throws IOException {
    JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
    DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
    Path classes = Files.createDirectories(dir.resolve("classes"));
    try (StandardJavaFileManager files =
        compiler.getStandardFileManager(diagnostics, Locale.ROOT, StandardCharsets.UTF_8)) {
      List<String> options =
          List.of(
              "-Xlint:all",
              "-proc:none",
              "--release",
              "21",
              "-d",
              classes.toString(),
              "-classpath",
              String.join(File.pathSeparator, classPath()));
      boolean ok =
          compiler
              .getTask(
                  null,
                  files,
                  diagnostics,
                  options,
                  null,
                  files.getJavaFileObjectsFromPaths(sources))
              .call();
      List<String> found = new ArrayList<>();
      diagnostics.getDiagnostics().forEach(d -> found.add(d.toString()));
      if (!ok && found.isEmpty()) {
        found.add("the compiler failed without a diagnostic");
      }
      return found;
    }
  }

  private static String classPathText() throws IOException {
    return String.join(File.pathSeparator, classPath());
  }

  /**
   * The test's class path, the entries of a manifest-only jar (as surefire may launch tests with)
   * included.
   */
  private static List<String> classPath() throws IOException {
    List<String> entries = new ArrayList<>();
    for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
      entries.add(entry);
      if (!entry.endsWith(".jar")) {
        continue;
      }
      try (JarFile jar = new JarFile(entry)) {
        Manifest manifest = jar.getManifest();
        String more = manifest == null ? null : manifest.getMainAttributes().getValue("Class-Path");
        if (more == null) {
          continue;
        }
        for (String url : more.trim().split("\\s+")) {
          URI uri = Path.of(entry).toUri().resolve(url);
          entries.add(Path.of(uri).toString());
        }
      }
    }
    return entries;
  }
}
