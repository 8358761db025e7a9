package org.armgals.maam.sim.spi;

import org.armgals.maam.sim.AtomBody;

/**
 * What drives one atom: called once per control cycle, in the order of atom ids, on the thread
 * running the simulation. It reads the body's sensors and sets its actuators; it must not block.
 */
@FunctionalInterface
public interface Controller {

  /** Runs control cycle number {@code cycle} (0, 1, …) for {@code body}. */
  void onCycle(AtomBody body, long cycle);

  /** A controller that does nothing: the legs hold the targets they have (straight at first). */
  static Controller idle() {
    return (body, cycle) -> {};
  }
}
