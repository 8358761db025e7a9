package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A child JVM started {@link ChildJvm.Priority#LOWER} runs {@value ChildJvm.Priority#LOWER_BY}
 * steps of {@code nice} below the JVM that started it; one started {@link ChildJvm.Priority#SAME}
 * at its priority.
 */
class ChildJvmTest {
  @TempDir Path dir;

  /** A child's main: says it runs, then waits for the end of its standard input. */
  public static final class WaitingMain {
    private WaitingMain() {}

    public static void main(String[] args) throws IOException {
      System.out.println("running");
      System.out.flush();
      BufferedReader in =
          new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
      while (in.readLine() != null) {
        // nothing to do but wait for the end
      }
    }
  }

  @Test
  void aLowerChildRunsTenNiceStepsBelowItsParent() throws IOException {
    assumeTrue(Files.isReadable(Path.of("/proc/self/stat")), "needs /proc (Linux)");
    assumeTrue(ChildJvm.nice(System.getenv("PATH")).isPresent(), "needs nice on the PATH");
    int parent = niceness(ProcessHandle.current().pid());

    int lower = childNiceness(ChildJvm.Priority.LOWER, "lower.log");
    int same = childNiceness(ChildJvm.Priority.SAME, "same.log");

    assertThat(lower).isEqualTo(Math.min(19, parent + ChildJvm.Priority.LOWER_BY));
    assertThat(same).isEqualTo(parent);
  }

  @Test
  void niceIsFoundInTheDirectoriesOfThePathOnlyAsAnExecutableFile() throws IOException {
    assumeTrue(
        FileSystems.getDefault().supportedFileAttributeViews().contains("posix"),
        "makes a file executable the POSIX way");
    Path empty = Files.createDirectories(dir.resolve("empty"));
    Path plain = Files.createDirectories(dir.resolve("plain"));
    Files.writeString(plain.resolve("nice"), "not executable");
    Path bin = Files.createDirectories(dir.resolve("bin"));
    Path nice = bin.resolve("nice");
    Files.writeString(nice, "#!/bin/sh\nexit 0\n");
    Files.setPosixFilePermissions(nice, PosixFilePermissions.fromString("rwxr-xr-x"));
    String sep = java.io.File.pathSeparator;

    assertThat(ChildJvm.nice(empty + sep + plain + sep + sep + bin)).contains(nice);
    assertThat(ChildJvm.nice(empty + sep + plain)).isEmpty();
    assertThat(ChildJvm.nice("")).isEmpty();
    assertThat(ChildJvm.nice(null)).isEmpty();
  }

  /** Starts {@link WaitingMain} at {@code priority}; answers its niceness once it runs. */
  private int childNiceness(ChildJvm.Priority priority, String log) throws IOException {
    Path file = dir.resolve(log);
    try (ChildJvm child =
        ChildJvm.start(
            "a waiting JVM", WaitingMain.class, List.of(), Map.of(), file, "32m", priority)) {
      long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
      // it says it runs once java runs main: after nice has set its priority and exec'd java
      while (!(Files.exists(file) && Files.readString(file).contains("running"))) {
        assertThat(child.ended()).as("ended early: %s", child.tail()).isFalse();
        assertThat(System.nanoTime()).as("did not run within 60 s").isLessThan(deadline);
        LockSupport.parkNanos(5_000_000L);
      }
      return niceness(child.handle().pid());
    }
  }

  /** The niceness of process {@code pid}: field 19 of {@code /proc/<pid>/stat}. */
  private static int niceness(long pid) throws IOException {
    String stat = Files.readString(Path.of("/proc", Long.toString(pid), "stat"));
    // after "pid (comm) ", the fields from the third (state) on, split by spaces
    String[] fields = stat.substring(stat.lastIndexOf(')') + 2).trim().split(" ");
    return Integer.parseInt(fields[19 - 3]);
  }
}
