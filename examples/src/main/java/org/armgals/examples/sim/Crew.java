package org.armgals.examples.sim;

import java.util.List;
import org.armgals.examples.cli.Summary;

/**
 * What drives one run of a {@link SimExample}: its robots, meta levels and any runtime they need.
 * Used on the thread that runs the simulation, between cycles.
 */
public interface Crew extends AutoCloseable {

  /**
   * The example's own figures for the summary, after the common ones (distance, speed, energy,
   * adaptations, missed cycles): the gait it ended in, say.
   */
  default List<Summary.Entry> figures() {
    return List.of();
  }

  /**
   * Cycles the crew missed: control cycles whose commands came too late or not at all (an atom in
   * another runtime, say); zero for a crew that runs in the simulation's own cycle.
   */
  default long missedCycles() {
    return 0;
  }

  /**
   * The reflective side of the run ({@link Reflection}), if the crew's robots are kernel entities:
   * the run finishes it after the last cycle, which records the loop and sums it up.
   */
  default java.util.Optional<Reflection> reflection() {
    return java.util.Optional.empty();
  }

  /** Stops what the crew started (islands, runtimes, processes); the default does nothing. */
  @Override
  default void close() {}
}
