package org.armgals.gals;

/**
 * One behavior of a reactive entity, run once per cycle after the entity has taken the events of
 * the release (paper §5.3: "the threads execute one reactive cycle"). Reactions of one entity run
 * in the order they were added, on the entity's own thread; entities of one island run in parallel.
 *
 * @param <S> the type of the entity's state
 */
@FunctionalInterface
public interface Reaction<S> {

  /**
   * Reacts to one instant. Must not wait: an awaited value that is not there yet is tested again at
   * a later cycle (active wait).
   *
   * @throws Exception any failure: it is counted ({@link IslandStats#failures()}), logged and
   *     traced, and the entity's other reactions still run
   */
  void react(CycleContext<S> cycle) throws Exception;
}
