package org.armgals.active.jms;

import jakarta.jms.JMSException;
import jakarta.jms.Message;
import jakarta.jms.MessageConsumer;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.IntSupplier;
import org.apache.activemq.artemis.api.core.ActiveMQInterruptedException;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.IdleStrategy;
import org.armgals.active.spi.RemoteAnswer;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Receives the answers to a transport's requests and look-ups from its synchronous consumer of
 * {@code active/Future}, on the thread that waits for one whenever it can (decision 0032).
 *
 * <p>Leader and followers: at most one thread receives at a time, the one holding {@link #lead}. A
 * thread that waits for an answer ({@link #lead}) takes the lead if it is free and receives
 * answers, its own and any other, until its own is in; the broker's delivery then wakes the waiting
 * thread itself, as it wakes a plain JMS {@code receive}, with no listener thread in between. A
 * waiter that finds the lead taken parks; whoever leads completes its future. When nobody waits but
 * answers are due (a future read through {@code isDone} or a completion stage), a receiving thread
 * of the transport's own leads instead: it is woken when a leader leaves while answers are still
 * due, when such a future is looked at ({@link #observe}), and at every sweep of the reply timeouts
 * ({@link #nudge}), so an answer that nobody looks at is received within a sweep period.
 *
 * <p>Threading: {@link #lead}, {@link #observe} and {@link #nudge} from any thread; the consumer is
 * only ever used by the thread holding {@link #lead}, one at a time, as JMS requires of a session.
 * A virtual thread leads only on a JDK that does not pin it to its carrier while it waits inside
 * the client's {@code receive} (monitor waits of virtual threads unmount from JDK 24 on).
 */
final class AnswerReceiver implements RemoteAnswer.Receiver, AutoCloseable {
  private static final Logger LOG = LoggerFactory.getLogger(AnswerReceiver.class);

  /** The longest one {@code receive} waits before its thread looks at its future and time again. */
  static final long SLICE_MILLIS = 10;

  /** How long the receiving thread waits after a failed {@code receive} before it tries again. */
  private static final Duration BACKOFF = Duration.ofMillis(100);

  /** Whether a virtual thread may wait inside the client's {@code receive} without pinning. */
  static final boolean VIRTUAL_THREADS_MAY_LEAD = Runtime.version().feature() >= 24;

  private final MessageConsumer consumer;
  private final Consumer<Message> handler;
  private final IntSupplier due;
  private final BooleanSupplier connected;
  private final TimeSource time;
  private final String name;
  private final ReentrantLock lead = new ReentrantLock();
  private final Thread receiving;
  private final LongAdder byWaiters = new LongAdder();
  private final LongAdder byOwnThread = new LongAdder();
  private final LongAdder failures = new LongAdder();
  private final LogLimiter failureLog = new LogLimiter();
  private final IdleStrategy afterFailure = IdleStrategy.backoff(0, 0, BACKOFF, BACKOFF);
  private volatile @Nullable Thread leader;
  private volatile boolean closed;
  private volatile boolean drain;

  /**
   * @param consumer a synchronous consumer of this transport's answers, on a session of its own
   * @param handler takes one answer; never throws
   * @param due how many answers are awaited (requests and look-ups whose answer has not come)
   * @param connected whether the connection is up: while it is not, a {@code receive} may wait for
   *     the reconnection, so no waiter leads (the transport's own thread does)
   * @param time the transport's time, which waiters' deadlines are read on
   * @param name names the receiving thread
   */
  AnswerReceiver(
      MessageConsumer consumer,
      Consumer<Message> handler,
      IntSupplier due,
      BooleanSupplier connected,
      TimeSource time,
      String name) {
    this.consumer = consumer;
    this.handler = handler;
    this.due = due;
    this.connected = connected;
    this.time = time;
    this.name = name;
    this.receiving =
        Thread.ofPlatform()
            .name("armgals-jms-answers-" + name)
            .daemon(true)
            .unstarted(this::receiveWhileDue);
  }

  void start() {
    receiving.start();
  }

  @Override
  public boolean lead(RemoteAnswer<?> future, boolean timed, long deadline) {
    if (closed) {
      return false;
    }
    if ((Thread.currentThread().isVirtual() && !VIRTUAL_THREADS_MAY_LEAD)
        || !connected.getAsBoolean()) {
      observe();
      return false;
    }
    if (!lead.tryLock()) {
      return false; // the leader receives this future's answer too
    }
    boolean check = true;
    Thread previous = leader; // not null if this thread leads already, further up its stack
    leader = Thread.currentThread();
    try {
      while (!future.completed() && !closed) {
        long millis = SLICE_MILLIS;
        if (timed) {
          long remaining = deadline - time.nanoTime();
          if (remaining <= 0) {
            break;
          }
          millis = Math.min(millis, TimeUnit.NANOSECONDS.toMillis(remaining));
          if (millis == 0) {
            check = false; // under a millisecond left: the waiter parks it out
            break;
          }
        }
        if (!receiveOne(millis, byWaiters)) {
          check = false;
          break;
        }
      }
    } finally {
      leader = previous;
      leave();
    }
    return check && !closed;
  }

  @Override
  public void observe() {
    if (!lead.isLocked() && due.getAsInt() > 0) {
      LockSupport.unpark(receiving);
    }
  }

  /**
   * Called at every sweep of the reply timeouts: whatever came in meanwhile is received, answers
   * nobody waits for included, even when no answer is due, so that nothing sent to this transport
   * piles up on the broker unread and uncounted.
   */
  void nudge() {
    drain = true;
    LockSupport.unpark(receiving);
  }

  /** The thread receiving answers now, if any. */
  @Nullable Thread leader() {
    return leader;
  }

  /** Answers received by threads waiting for one, and by the transport's own receiving thread. */
  long receivedByWaiters() {
    return byWaiters.sum();
  }

  long receivedByOwnThread() {
    return byOwnThread.sum();
  }

  private void leave() {
    lead.unlock();
    if (due.getAsInt() > 0) {
      LockSupport.unpark(receiving);
    }
  }

  /** The transport's receiving thread: leads whenever answers are due and nobody else leads. */
  private void receiveWhileDue() {
    while (!closed) {
      if ((due.getAsInt() > 0 || drain) && lead.tryLock()) {
        boolean failed = false;
        leader = receiving;
        try {
          if (drain && connected.getAsBoolean()) {
            drain = false;
            failed = !receiveWhatIsThere();
          }
          while (!failed && !closed && due.getAsInt() > 0) {
            if (!receiveOne(SLICE_MILLIS, byOwnThread)) {
              failed = true;
              break;
            }
          }
        } finally {
          leader = null;
          lead.unlock();
        }
        if (failed && !closed) {
          afterFailure.idle();
        } else {
          afterFailure.reset();
        }
        continue;
      }
      LockSupport.park(this);
    }
  }

  /**
   * Receives one answer, waiting at most {@code millis}, and hands it on; false if the receive
   * failed (the consumer is closed, the connection failed, or the thread was interrupted, whose
   * flag is then set again for the waiter to see).
   */
  private boolean receiveOne(long millis, LongAdder count) {
    try {
      Message m = consumer.receive(millis);
      if (m != null) {
        count.increment();
        handler.accept(m);
      }
      return true;
    } catch (JMSException | RuntimeException e) {
      if (interrupted(e)) {
        Thread.currentThread().interrupt();
      } else if (!closed) {
        failures.increment();
        long n = failureLog.tick();
        if (n > 0) {
          LOG.warn("JMS transport {}: receiving answers failed ({} so far)", name, n, e);
        }
      }
      return false;
    }
  }

  /**
   * Receives every message the client holds already, waiting a millisecond at most for each (no
   * round trip to the broker, unlike {@code receiveNoWait}); false if a receive failed.
   */
  private boolean receiveWhatIsThere() {
    try {
      for (Message m = consumer.receive(1); m != null && !closed; m = consumer.receive(1)) {
        byOwnThread.increment();
        handler.accept(m);
      }
      return true;
    } catch (JMSException | RuntimeException e) {
      if (!closed) {
        failures.increment();
        LOG.debug("JMS transport {}: draining answers failed", name, e);
      }
      return false;
    }
  }

  private static boolean interrupted(Throwable e) {
    for (Throwable t = e; t != null; t = t.getCause()) {
      if (t instanceof InterruptedException || t instanceof ActiveMQInterruptedException) {
        return true;
      }
    }
    return false;
  }

  /**
   * Stops the receiving thread and makes leaders give up within a slice; the consumer itself is
   * closed with the transport's connection.
   */
  @Override
  public void close() {
    closed = true;
    LockSupport.unpark(receiving);
    try {
      receiving.join(TimeUnit.SECONDS.toMillis(10));
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
