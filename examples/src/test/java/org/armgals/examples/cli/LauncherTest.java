package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.concurrent.TimeUnit;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code ./armgals} launcher at the repository's root, run in a copy of the checkout's layout
 * whose Maven wrapper and JDK are stand-ins that say what they were asked: it rebuilds the jar when
 * one of armgals' own modules changed, and only then.
 */
class LauncherTest {
  private static final Path CHECKOUT = Path.of("").toAbsolutePath().getParent();
  private static final Instant BUILT = Instant.parse("2026-01-01T00:00:00Z");

  @TempDir Path root;

  private Path jdk;

  @BeforeEach
  void aCheckout() throws IOException {
    Files.copy(CHECKOUT.resolve("armgals"), root.resolve("armgals"));
    Files.createDirectories(root.resolve("scripts"));
    Files.copy(CHECKOUT.resolve("scripts/java.sh"), root.resolve("scripts/java.sh"));
    write(
        "pom.xml",
        "<project>\n  <modules>\n    <module>maam-sim</module>\n"
            + "    <module>examples</module>\n  </modules>\n</project>\n");
    write("maam-sim/pom.xml", "<project/>\n");
    write("maam-sim/src/main/java/Sim.java", "class Sim {}\n");
    write("examples/pom.xml", "<project/>\n");
    write("examples/src/main/java/Cli.java", "class Cli {}\n");
    write("examples/target/armgals.jar", "a jar\n");
    script("mvnw", "echo \"mvnw $*\" >> \"$(dirname \"$0\")/built\"\n");
    jdk = root.resolve("jdk");
    Files.createDirectories(jdk.resolve("bin"));
    Files.writeString(jdk.resolve("release"), "JAVA_VERSION=\"21.0.5\"\n");
    script("jdk/bin/java", "echo \"java $*\"\n");
    try (var files = Files.walk(root)) {
      for (Path file : files.toList()) {
        Files.setLastModifiedTime(file, FileTime.from(BUILT.minusSeconds(60)));
      }
    }
    Files.setLastModifiedTime(root.resolve("examples/target/armgals.jar"), FileTime.from(BUILT));
  }

  private void write(String file, String text) throws IOException {
    Path path = root.resolve(file);
    Files.createDirectories(path.getParent());
    Files.writeString(path, text, StandardCharsets.UTF_8);
  }

  private void script(String file, String body) throws IOException {
    write(file, "#!/usr/bin/env bash\n" + body);
    Files.setPosixFilePermissions(root.resolve(file), PosixFilePermissions.fromString("rwxr-xr-x"));
  }

  private void touch(String file) throws IOException {
    Files.setLastModifiedTime(root.resolve(file), FileTime.from(BUILT.plusSeconds(60)));
  }

  @Test
  void theJvmIsGivenTheOptionsThatKeepNettyAndArtemisQuietOnItsVersion() throws Exception {
    assertThat(launch())
        .startsWith("java --enable-native-access=ALL-UNNAMED -XX:+UseZGC -XX:+ZGenerational -jar ")
        .doesNotContain("unsafe");

    Files.writeString(jdk.resolve("release"), "JAVA_VERSION=\"25.0.1\"\n");
    assertThat(launch())
        .startsWith(
            "java --enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow"
                + " -XX:+UseZGC -jar ");
  }

  @Test
  void aCollectorNamedInTheOptionsIsTakenInsteadOfZgc() throws Exception {
    Files.writeString(jdk.resolve("release"), "JAVA_VERSION=\"25.0.1\"\n");

    assertThat(launch("-XX:+UseG1GC -Xmx2g"))
        .startsWith(
            "java --enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow"
                + " -XX:+UseG1GC -Xmx2g -jar ")
        .doesNotContain("ZGC");
    assertThat(launch("-Xmx2g")).contains(" -XX:+UseZGC -Xmx2g -jar ");
  }

  /** Runs the launcher with {@code list}; answers what it printed, both streams. */
  private String launch() throws IOException, InterruptedException {
    return launch(null);
  }

  /** As {@link #launch()}, with {@code ARMGALS_JAVA_OPTS} set to {@code options} if not null. */
  private String launch(@Nullable String options) throws IOException, InterruptedException {
    ProcessBuilder command = new ProcessBuilder("bash", root.resolve("armgals").toString(), "list");
    command.environment().put("JAVA_HOME", jdk.toString());
    command.environment().remove("ARMGALS_JAVA_OPTS");
    if (options != null) {
      command.environment().put("ARMGALS_JAVA_OPTS", options);
    }
    command.redirectErrorStream(true);
    Process process = command.start();
    String out = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
    assertThat(process.waitFor(30, TimeUnit.SECONDS)).isTrue();
    assertThat(process.exitValue()).as(out).isZero();
    return out;
  }

  @Test
  void anUpToDateJarRunsWithoutABuild() throws Exception {
    String out = launch();

    assertThat(out).contains("-jar " + root.resolve("examples/target/armgals.jar") + " list");
    assertThat(root.resolve("built")).doesNotExist();
  }

  @Test
  void anotherProjectInTheCheckoutDoesNotMakeTheJarStale() throws Exception {
    write("mybot/pom.xml", "<project/>\n");
    write("mybot/src/main/java/mybot/MybotRobot.java", "class MybotRobot {}\n");
    touch("mybot/pom.xml");
    touch("mybot/src/main/java/mybot/MybotRobot.java");

    String out = launch();

    assertThat(out).doesNotContain("building");
    assertThat(root.resolve("built")).doesNotExist();
  }

  @Test
  void aChangedSourceOrPomOfAModuleRebuildsTheJar() throws Exception {
    touch("maam-sim/src/main/java/Sim.java");
    assertThat(launch()).contains("building examples/target/armgals.jar");
    assertThat(Files.readString(root.resolve("built"))).contains("-pl examples -am package");

    Files.delete(root.resolve("built"));
    Files.setLastModifiedTime(
        root.resolve("maam-sim/src/main/java/Sim.java"), FileTime.from(BUILT.minusSeconds(1)));
    touch("examples/pom.xml");
    launch();
    assertThat(root.resolve("built")).exists();
  }
}
