package org.armgals.examples.live;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.armgals.active.TimeSource;
import org.armgals.examples.sim.Playback;
import org.armgals.examples.sim.RunWatcher;

/**
 * Plays a trace back ({@link Playback}) to a {@link RunWatcher} at the pace it was run, times a
 * speed, with pause and step: what {@code armgals view} does with the page's buttons. After the
 * last cycle it tells the end and stays there.
 *
 * <p>{@link #play} on one thread; {@link #command} from any other.
 */
public final class Player {
  /** The speeds {@code faster} and {@code slower} step through. */
  static final double[] SPEEDS = {0.125, 0.25, 0.5, 1, 2, 4, 8, 16};

  private final Playback playback;
  private final RunWatcher watcher;
  private final Duration period;
  private final TimeSource time;
  private final ReentrantLock lock = new ReentrantLock();
  private final Condition changed = lock.newCondition();
  private boolean paused;
  private int steps;
  private int speed = 3;
  private boolean stopped;

  /**
   * @param period the trace's control period: one cycle is played each period, divided by the speed
   * @param paused whether it starts paused
   */
  public Player(
      Playback playback, RunWatcher watcher, Duration period, TimeSource time, boolean paused) {
    this.playback = requireNonNull(playback, "playback");
    this.watcher = requireNonNull(watcher, "watcher");
    this.period = requireNonNull(period, "period");
    this.time = requireNonNull(time, "time");
    this.paused = paused;
  }

  /**
   * Does what the page asked: {@code pause}, {@code play}, {@code step} (one cycle, pausing),
   * {@code faster}, {@code slower} (doubling or halving the speed, from 1/8 to 16).
   *
   * @throws IllegalArgumentException another command
   */
  public void command(String command) {
    lock.lock();
    try {
      switch (command) {
        case "pause" -> paused = true;
        case "play" -> paused = false;
        case "step" -> {
          paused = true;
          steps++;
        }
        case "faster" -> speed = Math.min(SPEEDS.length - 1, speed + 1);
        case "slower" -> speed = Math.max(0, speed - 1);
        default ->
            throw new IllegalArgumentException(
                "'"
                    + command
                    + "' is not a command of the player; expected pause, play, step,"
                    + " faster or slower");
      }
      changed.signalAll();
    } finally {
      lock.unlock();
    }
  }

  /** Stops {@link #play} at once. */
  public void stop() {
    lock.lock();
    try {
      stopped = true;
      changed.signalAll();
    } finally {
      lock.unlock();
    }
  }

  /**
   * Plays every cycle, then tells the end and waits until {@link #stop}.
   *
   * @throws InterruptedException interrupted while it waited
   */
  public void play() throws InterruptedException {
    watcher.started(playback.start());
    long due = time.nanoTime();
    for (int i = 0; i < playback.size(); i++) {
      lock.lock();
      try {
        while (!stopped && paused && steps == 0) {
          changed.await();
          due = time.nanoTime();
        }
        if (stopped) {
          return;
        }
        if (steps > 0) {
          steps--;
        } else {
          long wait;
          while (!stopped && !paused && (wait = due - time.nanoTime()) > 0) {
            changed.awaitNanos(wait);
          }
          if (stopped) {
            return;
          }
          if (paused && steps == 0) {
            i--; // paused while it waited: this cycle is not played yet
            continue;
          }
          if (steps > 0) {
            steps--;
          }
        }
        due += (long) (period.toNanos() / SPEEDS[speed]);
      } finally {
        lock.unlock();
      }
      Playback.Cycle cycle = playback.cycle(i);
      cycle.loop().forEach(watcher::loop);
      watcher.frame(cycle.cycle(), cycle.frame());
    }
    watcher.ended(playback.end());
    lock.lock();
    try {
      while (!stopped) {
        changed.await();
      }
    } finally {
      lock.unlock();
    }
  }
}
