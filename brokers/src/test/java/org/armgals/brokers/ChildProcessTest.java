package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import org.armgals.active.TimeSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ChildProcessTest {
  private static final Duration LONG = Duration.ofSeconds(30);

  @TempDir Path dir;

  private ChildProcess bash(String script) {
    return ChildProcess.start(
        "test child",
        new ProcessBuilder("bash", "-c", script),
        dir.resolve("out.log"),
        TimeSource.system());
  }

  @Test
  void awaitLineReturnsTheFirstLineThatMatches() throws Exception {
    try (ChildProcess child = bash("echo starting; echo ready 1; echo ready 2; exec cat")) {
      assertThat(child.awaitLine("ready", line -> line.startsWith("ready"), LONG))
          .isEqualTo("ready 1");
      assertThat(child.isAlive()).isTrue();
    }
  }

  @Test
  void awaitLineFailsWithTheLastOutputWhenTheProcessEndsFirst() throws Exception {
    try (ChildProcess child = bash("echo cannot bind the port; exit 3")) {
      assertThatThrownBy(() -> child.awaitLine("ready", line -> line.equals("ready"), LONG))
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("ended before printing ready")
          .hasMessageContaining("cannot bind the port");
    }
  }

  @Test
  void awaitLineFailsAtItsDeadline() throws Exception {
    try (ChildProcess child = bash("echo waiting; exec cat")) {
      assertThatThrownBy(
              () -> child.awaitLine("ready", line -> line.equals("ready"), Duration.ofMillis(200)))
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("did not print ready within PT0.2S")
          .hasMessageContaining("waiting");
    }
  }

  @Test
  void outputGoesToTheLogFile() throws Exception {
    try (ChildProcess child = bash("echo first; echo second")) {
      assertThat(child.awaitExit(LONG)).isZero();
    }
    assertThat(java.nio.file.Files.readAllLines(dir.resolve("out.log")))
        .containsExactly("first", "second");
  }

  @Test
  void stopEndsTheProcessAndItsDescendants() throws Exception {
    ChildProcess child = bash("tail -f /dev/null & echo child $!; wait");
    long grandchild =
        Long.parseLong(
            child.awaitLine("child", line -> line.startsWith("child "), LONG).substring(6));
    Optional<ProcessHandle> handle = ProcessHandle.of(grandchild);
    assertThat(handle).isPresent();

    child.stop(LONG);

    assertThat(child.isAlive()).isFalse();
    assertThat(handle.get().onExit()).succeedsWithin(LONG);
  }

  @Test
  void stopKillsAProcessThatIgnoresTermination() throws Exception {
    ChildProcess child = bash("trap '' TERM; echo ready; exec tail -f /dev/null");
    child.awaitLine("ready", line -> line.equals("ready"), LONG);

    assertThat(child.stop(Duration.ofMillis(300))).isNull();
    assertThat(child.isAlive()).isFalse();
  }

  @Test
  void stopKeepsWhatTheProcessPrintsWhileItStops() throws Exception {
    ChildProcess child = bash("trap 'echo stopping; exit 7' TERM; echo ready; read -r line");
    child.awaitLine("ready", line -> line.equals("ready"), LONG);

    assertThat(child.stop(LONG)).isEqualTo(7);
    assertThat(child.tail()).endsWith("ready\nstopping");
    assertThat(java.nio.file.Files.readAllLines(dir.resolve("out.log")))
        .containsExactly("ready", "stopping");
  }

  @Test
  void killEndsTheProcessAtOnce() throws Exception {
    ChildProcess child = bash("trap '' TERM; echo ready; exec tail -f /dev/null");
    child.awaitLine("ready", line -> line.equals("ready"), LONG);

    child.kill();

    assertThat(child.isAlive()).isFalse();
  }

  @Test
  void freePortsAreDistinct() {
    List<Integer> ports = FreePorts.take(5);
    assertThat(ports).doesNotHaveDuplicates().allMatch(port -> port > 0 && port < 65536);
  }
}
