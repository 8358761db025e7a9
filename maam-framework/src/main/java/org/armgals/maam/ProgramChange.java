package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * A change to a robot's reactive program, as its {@link MetaRobot} applies it: what a robot's
 * registration methods make in its constructor, and what a request of its behavioral meta ({@link
 * RobotKind}: {@code setScheduling}, {@code changeModule}...) becomes once the robot has built its
 * parts from its kind's catalog. A change that would break the program (a cycle, an unknown name)
 * is rejected whole: the program stays as it was.
 */
final class ProgramChange {

  private ProgramChange() {}

  /** One change. */
  sealed interface Change
      permits SetScheduling, ChangeModule, AddSchema, RemoveSchema, AddConnector, RemoveConnector {}

  /**
   * Replaces the whole program: a new reactive program for a while (§5.1), completely rescheduled.
   *
   * @param schemas in schedule order
   * @param connectors joining them
   */
  record SetScheduling(List<Schema> schemas, List<Connector> connectors) implements Change {

    /** Copies the lists. */
    SetScheduling {
      schemas = List.copyOf(schemas);
      connectors = List.copyOf(connectors);
    }
  }

  /**
   * Replaces the module of the same name by {@code replacement}, of the same kind and ports; the
   * schedule and the connectors' state are kept.
   *
   * @param replacement the new module
   */
  record ChangeModule(BehaviorModule replacement) implements Change {

    /** Checks for null. */
    ChangeModule {
      requireNonNull(replacement, "replacement");
    }
  }

  /**
   * Adds a schema after the others; complete rescheduling.
   *
   * @param schema its name not used yet
   */
  record AddSchema(Schema schema) implements Change {

    /** Checks for null. */
    AddSchema {
      requireNonNull(schema, "schema");
    }
  }

  /**
   * Removes a schema, and the connectors to or from its modules; complete rescheduling.
   *
   * @param name the schema's name
   */
  record RemoveSchema(String name) implements Change {

    /** Checks for null. */
    RemoveSchema {
      requireNonNull(name, "name");
    }
  }

  /**
   * Adds a connector; complete rescheduling.
   *
   * @param connector between modules of the program
   */
  record AddConnector(Connector connector) implements Change {

    /** Checks for null. */
    AddConnector {
      requireNonNull(connector, "connector");
    }
  }

  /**
   * Removes a connector equal to {@code connector}; complete rescheduling.
   *
   * @param connector one of the program's
   */
  record RemoveConnector(Connector connector) implements Change {

    /** Checks for null. */
    RemoveConnector {
      requireNonNull(connector, "connector");
    }
  }
}
