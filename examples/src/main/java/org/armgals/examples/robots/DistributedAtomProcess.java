package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The JVM of one atom of {@link Distributed}: {@link DistributedAtomMain} on this JVM's class path
 * and Java, its output in a log file. It runs until its standard input ends: {@link #close} closes
 * it, and so does the end of this JVM, however it ends, so no atom outlives the world.
 */
final class DistributedAtomProcess implements AutoCloseable {
  private static final int TAIL_LINES = 20;

  private final int atom;
  private final Process process;
  private final Path log;

  private DistributedAtomProcess(int atom, Process process, Path log) {
    this.atom = atom;
    this.process = process;
    this.log = log;
  }

  /**
   * Starts the JVM of atom {@code atom} with {@code args} for {@link DistributedAtomMain}, and the
   * broker's credentials, if any, in its environment (not on its command line).
   *
   * @throws IllegalStateException the process could not be started, naming the atom and why
   */
  static DistributedAtomProcess start(
      int atom, List<String> args, Path log, String user, String password) {
    requireNonNull(args, "args");
    requireNonNull(log, "log");
    String java =
        ProcessHandle.current()
            .info()
            .command()
            .orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    ProcessBuilder command =
        new ProcessBuilder(
            java,
            "-Xmx128m",
            "-XX:TieredStopAtLevel=1",
            "-XX:+UseSerialGC",
            "-cp",
            System.getProperty("java.class.path"),
            DistributedAtomMain.class.getName());
    command.command().addAll(1, quiet(Runtime.version()));
    command.command().addAll(args);
    if (!user.isEmpty()) {
      command.environment().put(DistributedAtomMain.USER, user);
      command.environment().put(DistributedAtomMain.PASSWORD, password);
    }
    command.redirectErrorStream(true).redirectOutput(log.toFile());
    try {
      Files.createDirectories(log.toAbsolutePath().getParent());
      return new DistributedAtomProcess(atom, command.start(), log);
    } catch (IOException e) {
      throw new IllegalStateException(
          "cannot start the JVM of atom " + atom + " (" + java + "): " + e.getMessage(), e);
    }
  }

  /**
   * The options that let an atom's JVM (netty, Artemis) run on {@code version} without a {@code
   * WARNING:} on its console: native access for Artemis' libaio, and, from JDK 23 (24 warns by
   * default), netty's use of {@code sun.misc.Unsafe}.
   */
  static List<String> quiet(Runtime.Version version) {
    return version.feature() >= 23
        ? List.of("--enable-native-access=ALL-UNNAMED", "--sun-misc-unsafe-memory-access=allow")
        : List.of("--enable-native-access=ALL-UNNAMED");
  }

  int atom() {
    return atom;
  }

  ProcessHandle handle() {
    return process.toHandle();
  }

  /** What the process said last, for an error message. */
  String tail() {
    try {
      List<String> lines = Files.readAllLines(log, StandardCharsets.UTF_8);
      return String.join("\n", lines.subList(Math.max(0, lines.size() - TAIL_LINES), lines.size()));
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read " + log, e);
    }
  }

  @Override
  public String toString() {
    return "the JVM of atom " + atom + " (pid " + process.pid() + ", log " + log + ")";
  }

  /** Closes its standard input: it leaves the broker and exits, without waiting for it. */
  void leave() {
    try {
      process.getOutputStream().close();
    } catch (IOException e) {
      // The pipe is already broken: the process is ending, and close() waits for it.
    }
  }

  /**
   * Stops it: closes its standard input, so that it leaves the broker and exits, waits up to 10
   * seconds, then kills it. If interrupted, kills it at once and keeps the interrupt status.
   */
  @Override
  public void close() {
    leave();
    try {
      if (!process.waitFor(10, TimeUnit.SECONDS)) {
        process.destroyForcibly();
        process.waitFor(10, TimeUnit.SECONDS);
      }
    } catch (InterruptedException e) {
      process.destroyForcibly();
      Thread.currentThread().interrupt();
    }
  }
}
