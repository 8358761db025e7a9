package org.armgals.gals;

import java.util.Optional;
import org.armgals.active.FutureValue;
import org.jspecify.annotations.Nullable;

/**
 * An awaited value over the active-wait future arm-active hands a reactive object (or the future of
 * a request to another runtime, completed by the transport and read only here). Its status is
 * settled by its entity at the beginning of a cycle ({@link #settle}), on the entity's thread.
 */
final class Pending<R extends @Nullable Object> implements AwaitedValue<R> {
  final String reaction;
  final long deadline;
  private final FutureValue<R> future;
  private volatile Status status = Status.PENDING;
  private @Nullable R value;
  private @Nullable Throwable failure;

  Pending(String reaction, long deadline, FutureValue<R> future) {
    this.reaction = reaction;
    this.deadline = deadline;
    this.future = future;
  }

  /**
   * Settles the status at the beginning of cycle {@code instant}.
   *
   * @return whether it is settled (no longer pending)
   */
  boolean settle(long instant) {
    if (future.isDone()) {
      try {
        value = future.getValue();
        status = Status.AVAILABLE;
      } catch (RuntimeException e) {
        failure = e.getCause() != null ? e.getCause() : e;
        status = Status.FAILED;
      }
      return true;
    }
    if (instant >= deadline) {
      status = Status.TIMED_OUT;
      return true;
    }
    return false;
  }

  void cancel() {
    status = Status.CANCELLED;
  }

  @Override
  public Status status() {
    return status;
  }

  @Override
  public R value() {
    Status s = status;
    if (s != Status.AVAILABLE) {
      throw new IllegalStateException("awaited value is " + s + ", expected AVAILABLE");
    }
    return value;
  }

  @Override
  public Optional<Throwable> failure() {
    return Optional.ofNullable(failure);
  }

  @Override
  public String toString() {
    return "AwaitedValue[" + status + ", reaction=" + reaction + ", deadline=" + deadline + "]";
  }
}
