package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.jspecify.annotations.Nullable;

/**
 * A JVM a run starts for a part of itself (an atom's robot, a meta level): the main class {@code
 * main} on this JVM's class path and Java, its output in a log file, its secrets in its environment
 * (never on its command line). It runs until its standard input ends: {@link #close} closes it, and
 * so does the end of this JVM, however it ends, so that no child outlives its run.
 */
public final class ChildJvm implements AutoCloseable {
  private static final int TAIL_LINES = 20;

  private final String what;
  private final Process process;
  private final Path log;

  private ChildJvm(String what, Process process, Path log) {
    this.what = what;
    this.process = process;
    this.log = log;
  }

  /**
   * The CPU priority of a child JVM beside the JVM that starts it, where the system lets a process
   * start another below its own priority (a {@code nice} command on the {@code PATH}: Linux,
   * macOS); elsewhere both run at the same priority.
   */
  public enum Priority {
    /** The same as this JVM's. */
    SAME,
    /**
     * {@value #LOWER_BY} steps of {@code nice} below this JVM's: a part that keeps its own pace (a
     * meta level) yields the cores to the robots when both want them.
     */
    LOWER;

    /** How many steps of {@code nice} {@link #LOWER} is below this JVM. */
    public static final int LOWER_BY = 10;
  }

  /**
   * Starts {@code main} with {@code args} and {@code environment} in a JVM of its own, at this
   * JVM's priority.
   *
   * @param what what it is, for messages: {@code "the JVM of atom 2"}
   * @throws IllegalStateException it could not be started, saying why
   */
  public static ChildJvm start(
      String what, Class<?> main, List<String> args, Map<String, String> environment, Path log) {
    return start(what, main, args, environment, log, "192m", Priority.SAME);
  }

  /**
   * As {@link #start(String, Class, List, Map, Path)}, with a heap of at most {@code maxHeap} (as
   * {@code -Xmx} takes it: {@code "128m"}) and at {@code priority}.
   */
  public static ChildJvm start(
      String what,
      Class<?> main,
      List<String> args,
      Map<String, String> environment,
      Path log,
      String maxHeap,
      Priority priority) {
    requireNonNull(what, "what");
    requireNonNull(maxHeap, "maxHeap");
    requireNonNull(main, "main");
    requireNonNull(args, "args");
    requireNonNull(environment, "environment");
    requireNonNull(log, "log");
    requireNonNull(priority, "priority");
    String java =
        ProcessHandle.current()
            .info()
            .command()
            .orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    List<String> command = new ArrayList<>();
    if (priority == Priority.LOWER) {
      nice(System.getenv("PATH"))
          .ifPresent(
              nice ->
                  command.addAll(
                      List.of(nice.toString(), "-n", Integer.toString(Priority.LOWER_BY))));
    }
    command.add(java);
    command.addAll(quiet(Runtime.version()));
    command.addAll(
        List.of(
            "-Xmx" + maxHeap,
            "-XX:TieredStopAtLevel=1",
            "-XX:+UseSerialGC",
            "-cp",
            System.getProperty("java.class.path"),
            main.getName()));
    command.addAll(args);
    ProcessBuilder builder = new ProcessBuilder(command);
    builder.environment().putAll(environment);
    builder.redirectErrorStream(true).redirectOutput(log.toFile());
    try {
      Files.createDirectories(log.toAbsolutePath().getParent());
      return new ChildJvm(what, builder.start(), log);
    } catch (IOException e) {
      throw new IllegalStateException(
          "cannot start " + what + " (" + java + "): " + e.getMessage(), e);
    }
  }

  /**
   * The {@code nice} command among the directories of {@code path} (as the {@code PATH} variable
   * holds them), if one is there: it runs a command below its caller's priority ({@code nice -n
   * <steps> command...}), and it execs the command, so the child's process is the JVM's own.
   */
  static Optional<Path> nice(@Nullable String path) {
    if (path == null || path.isBlank()) {
      return Optional.empty();
    }
    for (String dir : path.split(java.io.File.pathSeparator)) {
      if (dir.isBlank()) {
        continue;
      }
      Path nice = Path.of(dir, "nice");
      if (Files.isRegularFile(nice) && Files.isExecutable(nice)) {
        return Optional.of(nice);
      }
    }
    return Optional.empty();
  }

  /**
   * The options that let a child JVM (netty, Artemis) run on {@code version} without a {@code
   * WARNING:} on its console: native access for Artemis' libaio, and, from JDK 23 (24 warns by
   * default), netty's use of {@code sun.misc.Unsafe}.
   */
  public static List<String> quiet(Runtime.Version version) {
    return version.feature() >= 23
        ? List.of("--enable-native-access=ALL-UNNAMED", "--sun-misc-unsafe-memory-access=allow")
        : List.of("--enable-native-access=ALL-UNNAMED");
  }

  /** Its process. */
  public ProcessHandle handle() {
    return process.toHandle();
  }

  /** Whether it has ended. */
  public boolean ended() {
    return !process.isAlive();
  }

  /** What it said last, for an error message. */
  public String tail() {
    try {
      List<String> lines = Files.readAllLines(log, StandardCharsets.UTF_8);
      return String.join("\n", lines.subList(Math.max(0, lines.size() - TAIL_LINES), lines.size()));
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read " + log, e);
    }
  }

  /** Its log. */
  public Path log() {
    return log;
  }

  @Override
  public String toString() {
    return what + " (pid " + process.pid() + ", log " + log + ")";
  }

  /**
   * Writes {@code line} to its standard input.
   *
   * @throws UncheckedIOException it has ended, or the pipe broke
   */
  public void say(String line) {
    requireNonNull(line, "line");
    try {
      process.getOutputStream().write((line + "\n").getBytes(StandardCharsets.UTF_8));
      process.getOutputStream().flush();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write to " + this, e);
    }
  }

  /** Closes its standard input: it leaves and exits, without waiting for it. */
  public void leave() {
    try {
      process.getOutputStream().close();
    } catch (IOException e) {
      // The pipe is broken already: the process is ending, and close() waits for it.
    }
  }

  /**
   * Stops it: closes its standard input, so that it leaves and exits, waits up to 10 seconds, then
   * kills it. If interrupted, kills it at once and keeps the interrupt status.
   */
  @Override
  public void close() {
    close(Duration.ofSeconds(10));
  }

  /**
   * Stops it: closes its standard input, so that it finishes and exits, waits up to {@code grace},
   * then kills it. If interrupted, kills it at once and keeps the interrupt status.
   */
  public void close(Duration grace) {
    leave();
    try {
      if (!process.waitFor(grace.toNanos(), TimeUnit.NANOSECONDS)) {
        process.destroyForcibly();
        process.waitFor(10, TimeUnit.SECONDS);
      }
    } catch (InterruptedException e) {
      process.destroyForcibly();
      Thread.currentThread().interrupt();
    }
  }

  /** Kills it at once (SIGKILL), as a crash would. */
  public void kill() {
    process.destroyForcibly();
  }
}
