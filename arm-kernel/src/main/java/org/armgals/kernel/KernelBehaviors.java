package org.armgals.kernel;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.armgals.representation.Behaviors;
import org.jspecify.annotations.Nullable;

/**
 * The kernel describing itself: the behaviors of structural and behavioral meta-entities in the
 * field representation. Running them changes only the description (a name added to a list); what
 * they stand for is done by the Java code of the meta-entity, which then applies the behavior to
 * its own activation so that its behavioral meta hears of it and replays it on its model.
 */
final class KernelBehaviors {
  private KernelBehaviors() {}

  static final String ADD_BEHAVIOR = "addBehavior";
  static final String DELETE_BEHAVIOR = "deleteBehavior";
  static final String NEW_INSTANCE = "newInstance";
  static final String ADD_BASE = "addBaseLevelEntity";
  static final String DELETE_BASE = "deleteBaseLevelEntity";

  /** The behaviors of plain entities, instances of {@code Entity}: none of their own. */
  static final Behaviors<FieldState> ENTITY = FieldBehaviors.of();

  /** The behaviors of structural meta-entities, instances of {@code StructuralMeta}. */
  static final Behaviors<FieldState> STRUCTURAL =
      FieldBehaviors.of(
          listing(ADD_BEHAVIOR, "behaviors", true),
          listing(DELETE_BEHAVIOR, "behaviors", false),
          listing(NEW_INSTANCE, "instances", true));

  /** The behaviors of behavioral meta-entities, instances of {@code BehavioralMeta}. */
  static final Behaviors<FieldState> BEHAVIORAL =
      FieldBehaviors.of(listing(ADD_BASE, "bases", true), listing(DELETE_BASE, "bases", false));

  /** The initial state of a structural meta named {@code name} with these behavior names. */
  static FieldState structural(String name, List<String> behaviors) {
    return new FieldState(
        Map.of("name", name, "behaviors", List.copyOf(behaviors), "instances", List.of()));
  }

  /** The initial state of a behavioral meta named {@code name}. */
  static FieldState behavioral(String name) {
    return new FieldState(Map.of("name", name, "bases", List.of()));
  }

  /** The initial state of a plain entity named {@code name}. */
  static FieldState plain(String name) {
    return new FieldState(Map.of("name", name));
  }

  private static FieldBehavior listing(String name, String field, boolean add) {
    return new FieldBehavior(
        name,
        (fields, input) -> {
          String item = Objects.requireNonNull((String) input, "input");
          List<Object> list = new ArrayList<>(listOf(fields.get(field)));
          list.remove(item);
          if (add) {
            list.add(item);
          }
          Map<String, Object> next = new HashMap<>(fields);
          next.put(field, List.copyOf(list));
          return next;
        });
  }

  private static List<?> listOf(@Nullable Object value) {
    return value instanceof List<?> l ? l : List.of();
  }
}
