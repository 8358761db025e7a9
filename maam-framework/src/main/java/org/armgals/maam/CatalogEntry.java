package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Step;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * A part of the program a robot kind's structural meta holds as one of its behaviors (paper §3.1:
 * the structural meta holds the behaviors of its instances): a schema, a module or a connector the
 * robots of the kind can be asked to run, by name, with parameters. It is a description, not a
 * step: the robot builds the part with {@link #build} when a request names it; applying the
 * behavior itself is refused.
 *
 * @param <R> the robots of the kind
 * @param <T> the part built
 */
final class CatalogEntry<R extends AbstractRobot, T> implements Behavior<PState> {

  /** What a catalog entry builds. */
  enum Part {
    SCHEMA("schema", Schema.class),
    MODULE("module", BehaviorModule.class),
    CONNECTOR("connector", Connector.class);

    final String word;
    final Class<?> type;

    Part(String word, Class<?> type) {
      this.word = word;
      this.type = type;
    }

    /** The behavior name of the entry {@code name}: {@code schema:climb}. */
    String behavior(String name) {
      return word + ":" + name;
    }
  }

  private final Part part;
  private final String name;
  private final Class<R> robots;
  private final RobotKind.Factory<R, T> factory;

  CatalogEntry(Part part, String name, Class<R> robots, RobotKind.Factory<R, T> factory) {
    this.part = requireNonNull(part, "part");
    this.name = RobotKind.checkName(name, part.word);
    this.robots = requireNonNull(robots, "robots");
    this.factory = requireNonNull(factory, "factory");
  }

  Part part() {
    return part;
  }

  /** The part's own name: {@code climb}. */
  String partName() {
    return name;
  }

  @Override
  public String name() {
    return part.behavior(name);
  }

  /**
   * Builds the part for {@code robot} with {@code parameters}, on the robot's thread.
   *
   * @throws IllegalArgumentException the robot is not of the kind's class, the parameters do not
   *     suit the part, or the factory built something of another name or type
   */
  Object build(AbstractRobot robot, Parameters parameters) {
    if (!robots.isInstance(robot)) {
      throw new IllegalArgumentException(
          name()
              + " builds for a "
              + robots.getSimpleName()
              + ", not for robot "
              + robot.name()
              + " (a "
              + robot.getClass().getSimpleName()
              + ")");
    }
    T built = factory.build(robots.cast(robot), parameters);
    if (!part.type.isInstance(built)) {
      throw new IllegalArgumentException(
          name() + " built " + built + "; expected a " + part.type.getSimpleName());
    }
    String builtName =
        switch (built) {
          case Schema s -> s.name();
          case BehaviorModule m -> m.name();
          default -> name;
        };
    if (!builtName.equals(name)) {
      throw new IllegalArgumentException(
          name() + " built a " + part.word + " named '" + builtName + "'; expected '" + name + "'");
    }
    return built;
  }

  @Override
  public boolean isApplicable(PState state, @Nullable Object input) {
    return false;
  }

  @Override
  public Step<PState> apply(PState state, @Nullable Object input) {
    throw new BehaviorNotApplicableException(name(), state);
  }

  @Override
  public String toString() {
    return "CatalogEntry[" + name() + " for " + robots.getSimpleName() + "]";
  }
}
