package org.armgals.kernel;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Behaviors;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PSpace;
import org.armgals.representation.p.PState;

/**
 * The kernel describing itself in the procedural representation (the P family): the states and
 * methods of structural and behavioral meta-entities. Running a method changes only the description
 * (a name added to a list); what it stands for is done by the Java code of the meta-entity, which
 * then applies the method to its own activation so that its behavioral meta hears of it and replays
 * it on its model, as for any procedural entity.
 */
final class KernelBehaviors {
  private KernelBehaviors() {}

  static final String ADD_BEHAVIOR = "addBehavior";
  static final String DELETE_BEHAVIOR = "deleteBehavior";
  static final String NEW_INSTANCE = "newInstance";
  static final String ADD_BASE = "addBaseLevelEntity";
  static final String DELETE_BASE = "deleteBaseLevelEntity";

  /**
   * The space of structural meta-entities: a name, the behaviors of the instances, the instances.
   */
  static final PSpace STRUCTURAL_SPACE = PSpace.of(structural("", List.of()));

  /** The space of behavioral meta-entities: a name and the base-level entities. */
  static final PSpace BEHAVIORAL_SPACE = PSpace.of(behavioral(""));

  /** The space of plain entities, instances of {@code Entity}: a name. */
  static final PSpace ENTITY_SPACE = PSpace.of(plain(""));

  /** The behaviors of plain entities, instances of {@code Entity}: none of their own. */
  static final Behaviors<PState> ENTITY = ENTITY_SPACE.methods();

  /** The behaviors of structural meta-entities, instances of {@code StructuralMeta}. */
  static final Behaviors<PState> STRUCTURAL =
      STRUCTURAL_SPACE.methods(
          listing(ADD_BEHAVIOR, "behaviors", true),
          listing(DELETE_BEHAVIOR, "behaviors", false),
          listing(NEW_INSTANCE, "instances", true));

  /** The behaviors of behavioral meta-entities, instances of {@code BehavioralMeta}. */
  static final Behaviors<PState> BEHAVIORAL =
      BEHAVIORAL_SPACE.methods(
          listing(ADD_BASE, "bases", true), listing(DELETE_BASE, "bases", false));

  /** The initial state of a structural meta named {@code name} with these behavior names. */
  static PState structural(String name, List<String> behaviors) {
    return new PState(
        Map.of("name", name, "behaviors", List.copyOf(behaviors), "instances", List.of()));
  }

  /** The initial state of a behavioral meta named {@code name}. */
  static PState behavioral(String name) {
    return new PState(Map.of("name", name, "bases", List.of()));
  }

  /** The initial state of a plain entity named {@code name}. */
  static PState plain(String name) {
    return new PState(Map.of("name", name));
  }

  /**
   * A method adding its input, a name, at the end of list field {@code field} (moving it there if
   * it is in already), or removing it; applicable to a name only.
   */
  private static PMethod listing(String name, String field, boolean add) {
    return PMethod.of(
            name,
            (state, input) -> {
              List<Object> list = new ArrayList<>((List<?>) state.get(field));
              list.remove(input);
              if (add) {
                list.add(input);
              }
              return state.with(field, List.copyOf(list));
            })
        .when((state, input) -> input instanceof String);
  }
}
