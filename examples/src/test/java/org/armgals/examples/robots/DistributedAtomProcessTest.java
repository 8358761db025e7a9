package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.armgals.examples.sim.ChildJvm;
import org.junit.jupiter.api.Test;

/** The JVM options of an atom's process keep its console free of the JDK's warnings. */
class DistributedAtomProcessTest {

  /** Runs {@link QuietJvmMain} on this JDK with {@code options}; answers what it printed. */
  private static String run(List<String> options) throws IOException, InterruptedException {
    List<String> command = new ArrayList<>();
    command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    command.addAll(options);
    command.addAll(
        List.of("-cp", System.getProperty("java.class.path"), QuietJvmMain.class.getName()));
    Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
    String out = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
    assertThat(process.waitFor(60, TimeUnit.SECONDS)).isTrue();
    assertThat(process.exitValue()).as(out).isZero();
    return out;
  }

  @Test
  void anAtomsJvmUsesNettyAndLibaioWithoutAWarning() throws Exception {
    String quiet = run(ChildJvm.quiet(Runtime.version()));

    assertThat(quiet).contains("netty unsafe").contains("libaio").doesNotContain("WARNING");
    if (Runtime.version().feature() >= 24) {
      // what the options prevent: JDK 24 and later warn about both by default
      assertThat(run(List.of())).contains("WARNING: A terminally deprecated method in sun.misc");
    }
  }

  @Test
  void theUnsafeOptionIsGivenOnlyToAJdkThatKnowsIt() {
    assertThat(ChildJvm.quiet(Runtime.Version.parse("21.0.5")))
        .containsExactly("--enable-native-access=ALL-UNNAMED");
    assertThat(ChildJvm.quiet(Runtime.Version.parse("25")))
        .containsExactly(
            "--enable-native-access=ALL-UNNAMED", "--sun-misc-unsafe-memory-access=allow");
  }
}
