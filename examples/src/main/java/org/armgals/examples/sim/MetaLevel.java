package org.armgals.examples.sim;

import java.util.List;
import java.util.Map;
import org.armgals.examples.run.Summary;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.BMetaRobot;
import org.armgals.representation.p.PState;

/**
 * The meta level of an example (paper figure 8): its behavioral meta-entities and the robots each
 * reflects on, described so that a run makes them in the robots' JVM or in another one ({@code
 * --meta local|remote}) with the same code. Made by {@link SimExample#metaLevel} for each run, on
 * each side; it refers to robots by name only, never to their objects, which live in the robots'
 * JVM.
 */
public interface MetaLevel {

  /**
   * Defines in {@code kernel} the kinds of the example's robots, by robot name: in the robots' JVM,
   * the kinds the robots are started with; in another JVM, the copies the metas model them in (the
   * same definitions: behaviors are code, and both sides know them).
   */
  Map<String, StructuralMeta<PState>> kinds(Kernel kernel);

  /**
   * The meta-entities, not started, each with the robots it takes and the filter it starts with.
   *
   * @param notes where a meta tells what it saw or decided, beside its requests
   */
  List<Watch> watches(MetaNotes notes);

  /**
   * The meta level's own figures for the run's summary, read after the run on the meta's side
   * (steps judged, the draw it measured...).
   */
  default List<Summary.Entry> figures() {
    return List.of();
  }

  /**
   * A meta-entity and what it watches.
   *
   * @param meta the meta-entity
   * @param robots the names of the robots it takes as base entities
   * @param filter the selector of their notifications it starts with (blank: all)
   */
  record Watch(BMetaRobot meta, List<String> robots, String filter) {
    /** Checks and copies. */
    public Watch {
      java.util.Objects.requireNonNull(meta, "meta");
      robots = List.copyOf(robots);
      java.util.Objects.requireNonNull(filter, "filter");
    }
  }

  /**
   * Where a meta level tells what it saw or decided, beside its requests (which carry their own
   * reasons): the reflective loop's record puts each note at the cycle of the base level's time it
   * names. Thread-safe.
   */
  @FunctionalInterface
  interface MetaNotes {
    /**
     * Notes {@code text} about robot {@code robot} at the base level's time {@code nanoTime} (the
     * meta's {@code context.nanoTime()}).
     */
    void note(String robot, long nanoTime, String text);
  }
}
