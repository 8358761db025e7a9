package org.armgals.brokers;

import static java.util.Objects.requireNonNull;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.armgals.active.TimeSource;
import org.jspecify.annotations.Nullable;

/**
 * A process started by a test: its output (stdout and stderr merged) is copied line by line to a
 * log file and kept, so that a test can wait for a line with a deadline instead of sleeping, and a
 * failure can show what the process said. A JVM shutdown hook kills the process (and its
 * descendants) if the test JVM ends without closing it.
 *
 * <p>Thread-safe: one pump thread reads the output; {@link #awaitLine} may be called from any
 * thread and returns once the pump has seen the line (the line happens-before the return).
 */
final class ChildProcess implements AutoCloseable {
  private static final int TAIL_LINES = 40;

  private final String name;
  private final Process process;
  private final Path log;
  private final TimeSource time;
  private final Thread killer;
  private final List<String> lines = new ArrayList<>();
  private boolean ended;

  private ChildProcess(String name, Process process, Path log, TimeSource time) {
    this.name = name;
    this.process = process;
    this.log = log;
    this.time = time;
    this.killer = new Thread(this::killNow, "kill " + name);
  }

  /**
   * Starts {@code command}, its output going to {@code log}. The caller owns the result and must
   * close it.
   */
  static ChildProcess start(String name, ProcessBuilder command, Path log, TimeSource time) {
    requireNonNull(name, "name");
    requireNonNull(command, "command");
    requireNonNull(log, "log");
    requireNonNull(time, "time");
    Process process;
    try {
      Files.createDirectories(log.toAbsolutePath().getParent());
      process = command.redirectErrorStream(true).start();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot start " + name + ": " + command.command(), e);
    }
    ChildProcess child = new ChildProcess(name, process, log, time);
    Runtime.getRuntime().addShutdownHook(child.killer);
    Thread.ofPlatform().daemon().name("output of " + name).start(child::pump);
    return child;
  }

  private void pump() {
    try (BufferedReader in =
            new BufferedReader(
                new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        Writer out = Files.newBufferedWriter(log, StandardCharsets.UTF_8)) {
      for (String line = in.readLine(); line != null; line = in.readLine()) {
        out.write(line);
        out.write('\n');
        out.flush();
        synchronized (this) {
          lines.add(line);
          notifyAll();
        }
      }
    } catch (IOException e) {
      synchronized (this) {
        lines.add("[harness] reading the output of " + name + " failed: " + e);
      }
    } finally {
      synchronized (this) {
        ended = true;
        notifyAll();
      }
    }
  }

  /**
   * Waits until the process prints a line that {@code wanted} accepts, and returns it.
   *
   * @throws IllegalStateException if the process ends first, or {@code timeout} passes; the message
   *     holds the last lines of its output
   */
  String awaitLine(String what, Predicate<String> wanted, Duration timeout)
      throws InterruptedException {
    long deadline = time.nanoTime() + timeout.toNanos();
    int seen = 0;
    synchronized (this) {
      while (true) {
        for (; seen < lines.size(); seen++) {
          if (wanted.test(lines.get(seen))) {
            return lines.get(seen);
          }
        }
        if (ended) {
          throw new IllegalStateException(
              name + " ended before printing " + what + "; its last lines:\n" + tail());
        }
        long left = deadline - time.nanoTime();
        if (left <= 0) {
          throw new IllegalStateException(
              name
                  + " did not print "
                  + what
                  + " within "
                  + timeout
                  + "; its last lines:\n"
                  + tail());
        }
        TimeUnit.NANOSECONDS.timedWait(this, left);
      }
    }
  }

  /** Waits for the process to exit by itself and returns its exit code. */
  int awaitExit(Duration timeout) throws InterruptedException {
    if (!process.waitFor(timeout.toNanos(), TimeUnit.NANOSECONDS)) {
      killNow();
      throw new IllegalStateException(
          name + " did not exit within " + timeout + "; killed it. Its last lines:\n" + tail());
    }
    awaitOutputEnd(timeout);
    return process.exitValue();
  }

  private synchronized void awaitOutputEnd(Duration timeout) throws InterruptedException {
    long deadline = time.nanoTime() + timeout.toNanos();
    for (long left = timeout.toNanos(); !ended && left > 0; left = deadline - time.nanoTime()) {
      TimeUnit.NANOSECONDS.timedWait(this, left);
    }
  }

  /** Closes the process's standard input: it reads end of file. */
  void closeInput() throws IOException {
    process.getOutputStream().close();
  }

  boolean isAlive() {
    return process.isAlive();
  }

  long pid() {
    return process.pid();
  }

  /** The last lines the process printed, one per line. */
  synchronized String tail() {
    return String.join("\n", lines.subList(Math.max(0, lines.size() - TAIL_LINES), lines.size()));
  }

  /**
   * Asks the process (and its descendants) to terminate, waits up to {@code grace}, then kills what
   * is left. Returns the exit code, or null if it had to be killed. The lines the process prints
   * while it stops still reach the log: the signals go through its {@link ProcessHandle}, because
   * {@link Process#destroy} also closes our end of its output, after which a process that writes,
   * or one that watches its output as {@code tail -f} does, dies of SIGPIPE.
   */
  @Nullable Integer stop(Duration grace) throws InterruptedException {
    process.descendants().forEach(ProcessHandle::destroy);
    process.toHandle().destroy();
    boolean exited = process.waitFor(grace.toNanos(), TimeUnit.NANOSECONDS);
    if (!exited) {
      killNow();
      process.waitFor(grace.toNanos(), TimeUnit.NANOSECONDS);
    }
    awaitOutputEnd(grace);
    forgetHook();
    return exited ? process.exitValue() : null;
  }

  /** Kills the process and its descendants at once (SIGKILL), as a crash would. */
  void kill() throws InterruptedException {
    killNow();
    process.waitFor();
    forgetHook();
  }

  private void killNow() {
    process.descendants().forEach(ProcessHandle::destroyForcibly);
    process.toHandle().destroyForcibly();
  }

  private void forgetHook() {
    try {
      Runtime.getRuntime().removeShutdownHook(killer);
    } catch (IllegalStateException e) {
      // The JVM is shutting down: the hook is running or has run, and kills the process anyway.
    }
  }

  /**
   * Stops the process: terminate, then kill after ten seconds. If interrupted meanwhile, kills it
   * at once and keeps the interrupt status.
   */
  @Override
  public void close() {
    try {
      if (process.isAlive()) {
        stop(Duration.ofSeconds(10));
      }
    } catch (InterruptedException e) {
      killNow();
      Thread.currentThread().interrupt();
    } finally {
      forgetHook();
    }
  }

  @Override
  public String toString() {
    return name + " (pid " + process.pid() + ", log " + log + ")";
  }
}
