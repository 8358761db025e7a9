package org.armgals.examples.cli;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;
import org.armgals.examples.robots.Caterpillar;
import org.armgals.examples.robots.Distributed;
import org.armgals.examples.robots.EnergySaver;
import org.armgals.examples.robots.ObstacleRobot;
import org.armgals.examples.robots.Reconfigure;
import org.armgals.examples.robots.Walker;
import org.armgals.examples.run.Example;

/** The examples {@code armgals} knows, in the order {@code armgals list} shows them. */
public final class Catalog {
  private final List<Example> examples;

  private Catalog(List<Example> examples) {
    this.examples = List.copyOf(examples);
  }

  /** The examples shipped with armgals. */
  public static Catalog standard() {
    return of(
        List.of(
            new Walker(),
            new Caterpillar(),
            new ObstacleRobot(),
            new EnergySaver(),
            EnergySaver.withoutMetaLevel(),
            new Reconfigure(),
            new Distributed(),
            new DemoExample()));
  }

  /**
   * A catalog of these examples.
   *
   * @throws IllegalArgumentException if two have the same name, naming it
   */
  public static Catalog of(List<? extends Example> examples) {
    requireNonNull(examples, "examples");
    long distinct = examples.stream().map(Example::name).distinct().count();
    if (distinct != examples.size()) {
      throw new IllegalArgumentException(
          "example names must be unique: "
              + examples.stream().map(Example::name).collect(Collectors.joining(", ")));
    }
    return new Catalog(List.copyOf(examples));
  }

  /** All of them, in order. */
  public List<Example> all() {
    return examples;
  }

  /** The example of that name, if there is one. */
  public Optional<Example> find(String name) {
    requireNonNull(name, "name");
    return examples.stream().filter(e -> e.name().equals(name)).findFirst();
  }
}
