package org.armgals.examples.sim;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Whether a run has been asked to stop before its end, and the wait that lets it finish first.
 * {@link #onCtrlC} asks when the JVM begins to shut down (Ctrl-C, SIGTERM): its shutdown hook then
 * waits, at most {@link #GRACE_SECONDS}, until the run has kept what it had and {@link #close
 * closed} this, so that the JVM ends after the run's last word rather than in the middle of a line.
 * {@link #requested} may be read from any thread; {@link #request} called from any.
 */
final class Interruption implements AutoCloseable {
  /** How long the JVM's shutdown waits for an interrupted run to keep its outputs. */
  static final long GRACE_SECONDS = 30;

  private final AtomicBoolean requested = new AtomicBoolean();
  private final CountDownLatch closed = new CountDownLatch(1);
  private final Thread hook;

  private Interruption(boolean onShutdown) {
    this.hook = new Thread(this::onShutdown, "armgals-interrupt");
    if (onShutdown) {
      Runtime.getRuntime().addShutdownHook(hook);
    }
  }

  /** Asked when the JVM begins to shut down. */
  static Interruption onCtrlC() {
    return new Interruption(true);
  }

  /** Asked by {@link #request} only. */
  static Interruption manual() {
    return new Interruption(false);
  }

  boolean requested() {
    return requested.get();
  }

  void request() {
    requested.set(true);
  }

  private void onShutdown() {
    request();
    try {
      closed.await(GRACE_SECONDS, TimeUnit.SECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /** The run is over: the JVM may end. */
  @Override
  public void close() {
    closed.countDown();
    try {
      Runtime.getRuntime().removeShutdownHook(hook);
    } catch (IllegalStateException e) {
      // The JVM is shutting down: the hook is running, and ends now that this is closed.
    }
  }
}
