package org.armgals.maam;

import java.util.List;

/**
 * The scheduling meta level of a robot (paper §5.4, class {@code MetaRobot}): it holds the robot's
 * reactive program (schemas and connectors), applies the changes the robot's registration methods
 * and its behavioral meta's requests make, and reschedules it completely with its {@link Scheduler}
 * at each change of schemas or connectors. What it shows here is read-only.
 *
 * <p>Threading: used by its robot's thread only (or by one thread before the robot runs).
 */
public sealed interface MetaRobot permits MetaRobotImpl {

  /** An empty program scheduled by {@code scheduler}. */
  static MetaRobot create(Scheduler scheduler) {
    return new MetaRobotImpl(scheduler);
  }

  /** The schemas, in schedule order. */
  List<Schema> schemas();

  /** The connectors, in the order added. */
  List<Connector> connectors();

  /** The current schedule. */
  Schedule schedule();

  /** Counts the changes applied; a robot recompiles its cycle when it moves. */
  long version();
}
