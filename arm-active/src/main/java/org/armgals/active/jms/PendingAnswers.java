package org.armgals.active.jms;

import java.time.Duration;
import java.util.Iterator;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.ActiveException;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.RemoteAnswer;
import org.jspecify.annotations.Nullable;

/**
 * The futures of requests and look-ups sent over a transport, by correlation number, until their
 * answer comes or their time runs out. Thread-safe.
 */
final class PendingAnswers {
  private record Pending(
      RemoteAnswer<Object> future, String target, @Nullable String runtime, long deadline) {}

  private final ConcurrentHashMap<Long, Pending> pending = new ConcurrentHashMap<>();
  private final AtomicLong next = new AtomicLong();
  private final TimeSource time;
  private final Duration timeout;

  PendingAnswers(TimeSource time, Duration timeout) {
    this.time = time;
    this.timeout = timeout;
  }

  /**
   * A new pending future for an answer from {@code target}, an object of {@code runtime} (null: no
   * runtime in particular, a look-up); its correlation number is returned. The reply timeout counts
   * from now.
   */
  long open(RemoteAnswer<Object> future, String target, @Nullable String runtime) {
    long corr = next.incrementAndGet();
    pending.put(corr, new Pending(future, target, runtime, time.nanoTime() + timeout.toNanos()));
    return corr;
  }

  /** Fails, with {@code cause}, the futures of answers from objects of {@code runtime}. */
  int failRuntime(String runtime, ActiveException cause) {
    int n = 0;
    for (Map.Entry<Long, Pending> e : pending.entrySet()) {
      Pending p = e.getValue();
      if (runtime.equals(p.runtime()) && pending.remove(e.getKey(), p)) {
        p.future().abandon(cause);
        n++;
      }
    }
    return n;
  }

  /** The future waiting for {@code corr}, taken out; null if unknown (late or duplicate answer). */
  @Nullable RemoteAnswer<Object> take(long corr) {
    Pending p = pending.remove(corr);
    return p == null ? null : p.future();
  }

  /** Fails the futures whose time ran out; returns how many. */
  int expire() {
    long now = time.nanoTime();
    int n = 0;
    for (Iterator<Map.Entry<Long, Pending>> it = pending.entrySet().iterator(); it.hasNext(); ) {
      Pending p = it.next().getValue();
      if (now - p.deadline() >= 0) {
        it.remove();
        p.future().abandon(new FutureTimeoutException(p.target(), timeout));
        n++;
      }
    }
    return n;
  }

  /** Fails every pending future with {@code cause}. */
  void abandonAll(ActiveException cause) {
    for (Iterator<Pending> it = pending.values().iterator(); it.hasNext(); ) {
      Pending p = it.next();
      it.remove();
      p.future().abandon(cause);
    }
  }

  int size() {
    return pending.size();
  }
}
