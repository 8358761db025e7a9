package org.armgals.maam;

import java.util.List;
import java.util.stream.Collectors;
import org.armgals.gals.Island;
import org.armgals.gals.ReactiveEntity;

/**
 * Runs a robot as a reactive entity of an arm-gals island (paper §5.3: a robot is a reactive
 * entity): its cycle is the entity's one reaction, and its adaptation requests are the entity's,
 * applied by the island at its adaptation point. The one class that knows how a robot is hosted
 * (decision 0026).
 */
final class IslandHost {

  private IslandHost() {}

  static ReactiveEntity<AbstractRobot> start(AbstractRobot robot, Island island) {
    return island.spawn(robot.name(), robot, cycle -> cycle.state().islandCycle(cycle));
  }

  /** Hands {@code adaptation} to the island, which applies it between two instants. */
  static void request(ReactiveEntity<AbstractRobot> entity, Adaptation adaptation) {
    entity.adapt(describe(adaptation), robot -> robot.apply(adaptation));
  }

  /**
   * A line for the island's trace that depends only on names (no identities): the same program
   * gives the same trace on every run.
   */
  static String describe(Adaptation adaptation) {
    return switch (adaptation) {
      case Adaptation.SetScheduling s ->
          "setScheduling " + names(s.schemas()) + " " + s.connectors();
      case Adaptation.ChangeModule c -> "changeModule " + c.replacement().name();
      case Adaptation.AddSchema a -> "addSchema " + a.schema().name();
      case Adaptation.RemoveSchema r -> "removeSchema " + r.name();
      case Adaptation.AddConnector a -> "addConnector " + a.connector();
      case Adaptation.RemoveConnector r -> "removeConnector " + r.connector();
    };
  }

  private static String names(List<Schema> schemas) {
    return schemas.stream().map(Schema::name).collect(Collectors.joining(", ", "[", "]"));
  }
}
