package org.armgals.testkit;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.LongSupplier;
import org.armgals.active.ManualClock;

/**
 * Steps a test's world by hand, one instant at a time: the islands it drives (each an {@code
 * island::step}, in the order they were added), then its manual clock, which releases its
 * synchronous objects and {@link Probe}s. An instant of the stepper is one step of each.
 *
 * <p>An island is taken as its step method ({@code Stepper.of(clock).and(island::step)}), not as an
 * {@code Island}, so that the testkit does not depend on arm-gals and arm-gals' own tests can use
 * it; anything whose cycle is a method can be stepped the same way.
 *
 * <p>Immutable; {@link #and} gives a new stepper. Threading: one thread steps at a time, never from
 * inside an object released by what it steps (as {@link ManualClock#step()} requires).
 */
public final class Stepper {
  private final ManualClock clock;
  private final List<LongSupplier> islands;

  private Stepper(ManualClock clock, List<LongSupplier> islands) {
    this.clock = clock;
    this.islands = List.copyOf(islands);
  }

  /** A stepper of {@code clock} alone. */
  public static Stepper of(ManualClock clock) {
    return new Stepper(requireNonNull(clock, "clock"), List.of());
  }

  /** This stepper, stepping {@code island} too (after the islands it already steps). */
  public Stepper and(LongSupplier island) {
    requireNonNull(island, "island");
    List<LongSupplier> more = new ArrayList<>(islands);
    more.add(island);
    return new Stepper(clock, more);
  }

  /** The manual clock it steps. */
  public ManualClock clock() {
    return clock;
  }

  /** The clock's last instant, 0 before the first. */
  public long instant() {
    return clock.instant();
  }

  /**
   * Steps one instant: each island, then the clock.
   *
   * @return the clock's instant
   */
  public long step() {
    for (LongSupplier island : islands) {
      island.getAsLong();
    }
    return clock.step();
  }

  /**
   * Steps {@code instants} instants.
   *
   * @throws IllegalArgumentException {@code instants} is negative
   */
  public void step(long instants) {
    if (instants < 0) {
      throw new IllegalArgumentException("instants must be >= 0, was " + instants);
    }
    for (long i = 0; i < instants; i++) {
      step();
    }
  }

  /**
   * {@link #stepUntil(String, BooleanSupplier, long)} with the condition described as "the
   * condition".
   */
  public long stepUntil(BooleanSupplier condition, long maxInstants) {
    return stepUntil("the condition", condition, maxInstants);
  }

  /**
   * Steps until {@code condition} holds, checking it before the first step and after each: at most
   * {@code maxInstants} instants.
   *
   * @param what the condition in words, for the failure's message
   * @return the number of instants it stepped (0 if the condition held at once)
   * @throws AssertionError the condition did not hold after {@code maxInstants} instants; the
   *     message names it and the instants stepped
   * @throws IllegalArgumentException {@code maxInstants} is negative
   */
  public long stepUntil(String what, BooleanSupplier condition, long maxInstants) {
    requireNonNull(what, "what");
    requireNonNull(condition, "condition");
    if (maxInstants < 0) {
      throw new IllegalArgumentException("maxInstants must be >= 0, was " + maxInstants);
    }
    long first = clock.instant() + 1;
    for (long stepped = 0; ; stepped++) {
      if (condition.getAsBoolean()) {
        return stepped;
      }
      if (stepped == maxInstants) {
        throw new AssertionError(
            what
                + " did not hold within "
                + maxInstants
                + " instant(s)"
                + (maxInstants == 0 ? "" : " (instants " + first + " to " + clock.instant() + ")"));
      }
      step();
    }
  }

  @Override
  public String toString() {
    return "Stepper[clock at instant " + clock.instant() + ", " + islands.size() + " island(s)]";
  }
}
