package org.armgals.kernel;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.LongConsumer;

/**
 * The lock step of one reactive entity with its behavioral meta, on a manual clock ({@link
 * EntityOptions#lockStep()}): the barriers the entity has sent and the meta's answers to them. The
 * clock calls it before each release ({@link org.armgals.active.ManualClock#addReleaseGate}): the
 * stepping thread waits until the meta has answered every barrier the instant's adaptation point
 * needs, so the entity never waits inside its instant (a reactive object does not block) and the
 * instant starts with the same answers whatever the threads.
 *
 * <p>Threading: {@link #sent} and {@link #take} on the entity's object; {@link #answered} on the
 * kernel's lock-step desk; {@link #accept} on the clock's stepping thread. A lock orders them.
 */
final class LockStepGate implements LongConsumer {
  private final int latency;
  private final Duration timeout;
  private final ReentrantLock lock = new ReentrantLock();
  private final Condition answer = lock.newCondition();
  private final TreeSet<Long> unanswered = new TreeSet<>();
  private final NavigableMap<Long, List<AdaptationRequest>> answers = new TreeMap<>();
  private boolean free;
  private long timeouts;
  private String why = "";

  LockStepGate(int latency, Duration timeout) {
    this.latency = latency;
    this.timeout = timeout;
  }

  /** The entity sent the barrier of {@code instant}. */
  void sent(long instant) {
    lock.lock();
    try {
      unanswered.add(instant);
    } finally {
      lock.unlock();
    }
  }

  /** The meta answered the barrier of {@code instant} with {@code requests}. */
  void answered(long instant, List<AdaptationRequest> requests) {
    lock.lock();
    try {
      if (unanswered.remove(instant)) {
        answers.put(instant, List.copyOf(requests));
        answer.signalAll();
      }
    } finally {
      lock.unlock();
    }
  }

  /**
   * Before the release of {@code next}: waits until every barrier up to {@code next - latency} is
   * answered. If one is not within the timeout the entity runs free from then on.
   */
  @Override
  public void accept(long next) {
    long needed = next - latency;
    lock.lock();
    try {
      long left = timeout.toNanos();
      while (!free && !unanswered.isEmpty() && unanswered.first() <= needed) {
        if (left <= 0) {
          free = true;
          timeouts++;
          why = "no answer within " + timeout;
          return;
        }
        left = answer.awaitNanos(left);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IllegalStateException(
          "interrupted while the release of instant " + next + " waited for a meta in lock step",
          e);
    } finally {
      lock.unlock();
    }
  }

  /** The requests answered to the barriers up to {@code instant}, in instant order; removed. */
  List<AdaptationRequest> take(long instant) {
    lock.lock();
    try {
      List<AdaptationRequest> due = new ArrayList<>();
      Map<Long, List<AdaptationRequest>> head = answers.headMap(instant, true);
      head.values().forEach(due::addAll);
      head.clear();
      return due;
    } finally {
      lock.unlock();
    }
  }

  /**
   * Stops waiting for the meta at once, for {@code reason} (its runtime was reported lost, say): a
   * release waiting now returns, and the entity runs free from its next adaptation point. Any
   * thread.
   */
  void release(String reason) {
    lock.lock();
    try {
      if (!free) {
        free = true;
        why = reason;
        answer.signalAll();
      }
    } finally {
      lock.unlock();
    }
  }

  /** Why the entity runs free; empty while it does not. */
  String reason() {
    lock.lock();
    try {
      return why;
    } finally {
      lock.unlock();
    }
  }

  /** Whether a release stopped waiting for the meta: the entity runs free from then on. */
  boolean free() {
    lock.lock();
    try {
      return free;
    } finally {
      lock.unlock();
    }
  }

  /** How many times a release gave up waiting. */
  long timeouts() {
    lock.lock();
    try {
      return timeouts;
    } finally {
      lock.unlock();
    }
  }
}
