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
import java.util.concurrent.TimeUnit;

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
   * Starts {@code main} with {@code args} and {@code environment} in a JVM of its own.
   *
   * @param what what it is, for messages: {@code "the JVM of atom 2"}
   * @throws IllegalStateException it could not be started, saying why
   */
  public static ChildJvm start(
      String what, Class<?> main, List<String> args, Map<String, String> environment, Path log) {
    return start(what, main, args, environment, log, "192m");
  }

  /**
   * As {@link #start(String, Class, List, Map, Path)}, with a heap of at most {@code maxHeap} (as
   * {@code -Xmx} takes it: {@code "128m"}).
   */
  public static ChildJvm start(
      String what,
      Class<?> main,
      List<String> args,
      Map<String, String> environment,
      Path log,
      String maxHeap) {
    requireNonNull(what, "what");
    requireNonNull(maxHeap, "maxHeap");
    requireNonNull(main, "main");
    requireNonNull(args, "args");
    requireNonNull(environment, "environment");
    requireNonNull(log, "log");
    String java =
        ProcessHandle.current()
            .info()
            .command()
            .orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    List<String> command = new ArrayList<>();
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
