package org.armgals.examples.sim;

import java.util.List;
import org.armgals.examples.run.Summary;

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

  /**
   * After the last cycle: records the reflective loop into {@code dir} ({@value Reflection#LOOP})
   * and answers the summary's lines of it; the default finishes the {@link #reflection()}, if any.
   * A crew whose robots and meta level live in JVMs it starts itself merges their records ({@link
   * LoopRecord}).
   */
  default List<Summary.Entry> finish(java.nio.file.Path dir) {
    return reflection().map(r -> r.finish(dir)).orElse(List.of());
  }

  /**
   * Stops what the crew started (islands, runtimes, processes); the default closes the {@link
   * #reflection()}, if any.
   */
  @Override
  default void close() {
    reflection().ifPresent(Reflection::close);
  }
}
