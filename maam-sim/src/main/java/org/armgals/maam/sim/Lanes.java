package org.armgals.maam.sim;

import java.time.Duration;
import java.util.concurrent.locks.LockSupport;
import java.util.function.IntConsumer;
import org.armgals.active.spi.IdleStrategy;
import org.jspecify.annotations.Nullable;

/**
 * Runs a pass over the atoms on several threads (decision 0064): the atoms split into as many runs
 * of consecutive indexes as there are lanes, the calling thread taking the first and a worker
 * thread each of the others. A pass's work on an atom touches that atom alone, so the result is the
 * same on any number of lanes, bit for bit; what must happen in atom order (events, contacts) is
 * left to the caller, after the pass.
 *
 * <p>Between passes a worker spins a little, yields a little, then parks until the next pass wakes
 * it; the caller waits for the workers the same way, and the last to finish wakes it. Passes over
 * fewer atoms than {@link #MIN_PER_LANE} a lane run on the calling thread alone: handing them over
 * would cost more.
 */
final class Lanes implements AutoCloseable {

  /** The fewest atoms per lane worth a thread of its own. */
  static final int MIN_PER_LANE = 128;

  private final Worker[] workers;

  /**
   * A pass's work on one atom, told which lane runs it: the calling thread is lane 0 and worker
   * thread k lane k, in every pass, so a lane may keep scratch state of its own.
   */
  interface LaneWork {
    void accept(int lane, int index);
  }

  /** The pass being run: its work and number of atoms, published by {@link #pass}. */
  private @Nullable LaneWork work;

  private int count;

  /** The thread running the pass, which the workers wake when they are done. */
  private @Nullable Thread caller;

  /** How the calling thread waits for the workers (one strategy per waiting thread). */
  private final IdleStrategy callerIdle = waiting();

  /** Counts passes; a worker runs a pass when it sees a new one. */
  private volatile long pass;

  private volatile boolean closed;

  /**
   * {@code lanes} lanes (at least 1): {@code lanes - 1} worker threads, named after {@code name}.
   */
  Lanes(int lanes, String name) {
    if (lanes < 1) {
      throw new IllegalArgumentException(lanes + " lanes: expected at least 1");
    }
    workers = new Worker[lanes - 1];
    for (int i = 0; i < workers.length; i++) {
      workers[i] = new Worker(i + 1);
      Thread thread = new Thread(workers[i]::run, name + "-lane-" + (i + 1));
      thread.setDaemon(true);
      workers[i].thread = thread;
      thread.start();
    }
  }

  /** The number of lanes. */
  int lanes() {
    return workers.length + 1;
  }

  /**
   * Calls {@code work} with every index from 0 to {@code count - 1}, each once, those of a lane in
   * increasing order, and returns when all are done. A failure in any lane is thrown here.
   */
  void forEach(int count, IntConsumer work) {
    forEach(count, (lane, i) -> work.accept(i));
  }

  /**
   * As {@link #forEach(int, IntConsumer)}, telling {@code work} the lane each index runs on: a pass
   * small enough to run on the calling thread alone runs all of it as lane 0.
   */
  void forEach(int count, LaneWork work) {
    if (workers.length == 0 || count < MIN_PER_LANE * lanes()) {
      for (int i = 0; i < count; i++) {
        work.accept(0, i);
      }
      return;
    }
    this.work = work;
    this.count = count;
    this.caller = Thread.currentThread();
    long next = pass + 1;
    pass = next;
    for (Worker w : workers) {
      LockSupport.unpark(w.thread);
    }
    Throwable failure = null;
    try {
      run(work, 0, lanes(), count);
    } catch (RuntimeException | Error e) {
      // The workers are still at the pass: it ends only when they are done.
      failure = e;
    }
    for (Worker w : workers) {
      callerIdle.reset();
      while (w.done != next) {
        callerIdle.idle();
      }
      if (w.failure != null) {
        if (failure == null) {
          failure = w.failure;
        }
        w.failure = null;
      }
    }
    this.work = null;
    if (failure instanceof RuntimeException e) {
      throw e;
    }
    if (failure instanceof Error e) {
      throw e;
    }
    if (failure != null) {
      throw new IllegalStateException("a lane of the step failed", failure);
    }
  }

  private static void run(LaneWork work, int lane, int lanes, int count) {
    int from = (int) ((long) count * lane / lanes);
    int to = (int) ((long) count * (lane + 1) / lanes);
    for (int i = from; i < to; i++) {
      work.accept(lane, i);
    }
  }

  /** How a thread waits for another: a few microseconds awake, then parked until woken. */
  private static IdleStrategy waiting() {
    return IdleStrategy.backoff(200, 20, Duration.ofNanos(20_000), Duration.ofMillis(1));
  }

  /** Stops the workers. */
  @Override
  public void close() {
    closed = true;
    for (Worker w : workers) {
      LockSupport.unpark(w.thread);
    }
  }

  private final class Worker {
    final int lane;
    @Nullable Thread thread;

    /** The last pass this worker finished. */
    volatile long done;

    volatile @Nullable Throwable failure;

    Worker(int lane) {
      this.lane = lane;
    }

    void run() {
      IdleStrategy idle = waiting();
      long seen = 0;
      while (!closed) {
        long p = pass;
        if (p == seen) {
          idle.idle();
          continue;
        }
        idle.reset();
        seen = p;
        LaneWork w = work;
        if (w != null) {
          try {
            Lanes.run(w, lane, lanes(), count);
          } catch (RuntimeException | Error e) {
            failure = e;
          }
        }
        done = p;
        LockSupport.unpark(caller);
      }
    }
  }
}
