package org.armgals.gals;

import java.util.Optional;
import org.jspecify.annotations.Nullable;

/**
 * A value a reactive entity waits for actively (paper §5.2): a stimulus like any other, tested at
 * each cycle, never waited on. Its status changes only at the beginning of its entity's cycles,
 * before the reactions run, so every reaction of a cycle sees the same status.
 *
 * <p>Threading: read it from the reactions of the entity that asked for it (or between cycles).
 *
 * @param <R> the type of the value
 */
public interface AwaitedValue<R extends @Nullable Object> {

  /** Where an awaited value stands. */
  enum Status {
    /** Asked for; no answer yet. */
    PENDING,
    /** The answer arrived: {@link #value()} has it. */
    AVAILABLE,
    /** The target failed to answer: {@link #failure()} says why. */
    FAILED,
    /** No answer within the time-out; a late answer is ignored. */
    TIMED_OUT,
    /** The reaction that waited for it was removed; a late answer is ignored. */
    CANCELLED
  }

  /** Where it stands now. */
  Status status();

  /** Whether it is still {@link Status#PENDING}. */
  default boolean isPending() {
    return status() == Status.PENDING;
  }

  /**
   * The answer.
   *
   * @throws IllegalStateException the status is not {@link Status#AVAILABLE} (the message says
   *     which it is)
   */
  R value();

  /** Why the target failed, when the status is {@link Status#FAILED}. */
  Optional<Throwable> failure();
}
