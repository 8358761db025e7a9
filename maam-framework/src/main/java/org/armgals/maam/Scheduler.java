package org.armgals.maam;

import java.util.List;

/**
 * Orders a robot's behavior modules for one cycle (paper §5.4, class {@code Scheduler}). The rules
 * of {@link #topological()}:
 *
 * <ol>
 *   <li>the module graph has a node per module and an edge per wire (producer to consumer) and per
 *       connector (source module to target module); it must be a DAG;
 *   <li>each schema's modules keep their {@link Schema#partialSchedule partial schedule};
 *   <li>the full schedule is a topological order of the whole graph in which, among modules ready
 *       to run, the first in (schema order, then partial schedule order) runs first: the same
 *       program gives the same order every time;
 *   <li>a cycle is refused with a {@link CycleException} naming the modules on it.
 * </ol>
 *
 * <p>A scheduler is a pure function of its arguments; any thread may call it. Another scheduler may
 * order the modules otherwise, but what it returns must keep {@link Schedule}'s contract: every
 * module of the program once, each wire's and connector's source before its target. The robot
 * checks it whenever its program changes and refuses a schedule that breaks it with an {@link
 * IllegalStateException}, the program unchanged.
 */
@FunctionalInterface
public interface Scheduler {

  /**
   * The schedule of {@code schemas}, in the order given, joined by {@code connectors}.
   *
   * @throws IllegalArgumentException two modules of one name, or a connector naming a module or a
   *     port that is not there or joining incompatible types, or a derivator into an input already
   *     fed by a wire or another derivator
   * @throws CycleException the program's graph has a cycle
   */
  Schedule schedule(List<Schema> schemas, List<Connector> connectors);

  /** Kahn's algorithm over the merged partial schedules: see the rules above. */
  static Scheduler topological() {
    return TopologicalScheduler.INSTANCE;
  }
}
