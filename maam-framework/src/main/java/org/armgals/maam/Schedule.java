package org.armgals.maam;

import java.util.ArrayList;
import java.util.List;

/**
 * The order a robot runs its behavior modules in within one cycle: a topological order of the
 * module graph (see {@link Scheduler}).
 *
 * @param modules every module once, producers before consumers
 */
public record Schedule(List<BehaviorModule> modules) {

  /** Copies the list. */
  public Schedule {
    modules = List.copyOf(modules);
  }

  /** The modules' names, in order. */
  public List<String> names() {
    List<String> names = new ArrayList<>(modules.size());
    for (BehaviorModule module : modules) {
      names.add(module.name());
    }
    return names;
  }
}
