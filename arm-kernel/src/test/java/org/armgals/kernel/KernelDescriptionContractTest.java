package org.armgals.kernel;

import java.util.List;
import java.util.Map;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.RepresentationContract;
import org.armgals.representation.StateSpace;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PState;

/**
 * The kernel's description of its structural meta-entities (a name, the behaviors of their
 * instances, the instances) is a procedural entity like any other: the representation contract
 * holds for it, so that the basic behavioral meta models the kernel as it models the base level.
 */
class KernelDescriptionContractTest extends RepresentationContract<PState> {
  private static final PMethod EXTRA =
      PMethod.of("extra", (state, input) -> state.with("name", "renamed"));

  @Override
  protected StateSpace<PState> space() {
    return KernelBehaviors.STRUCTURAL_SPACE;
  }

  @Override
  protected Behaviors<PState> behaviors() {
    return KernelBehaviors.STRUCTURAL;
  }

  @Override
  protected Trigger applicable() {
    return new Trigger(KernelBehaviors.ADD_BEHAVIOR, "move");
  }

  @Override
  protected String inapplicable() {
    return KernelBehaviors.DELETE_BEHAVIOR; // with no name to delete
  }

  @Override
  protected List<Trigger> triggers() {
    return List.of(
        new Trigger(KernelBehaviors.ADD_BEHAVIOR, "move"),
        new Trigger(KernelBehaviors.NEW_INSTANCE, "robot1"),
        new Trigger(KernelBehaviors.ADD_BEHAVIOR, "turn"),
        new Trigger(KernelBehaviors.DELETE_BEHAVIOR, "move"));
  }

  @Override
  protected String idleTrigger() {
    return "noSuchKernelBehavior";
  }

  @Override
  protected Behavior<PState> extra() {
    return EXTRA;
  }

  @Override
  protected PState outside() {
    return KernelBehaviors.plain("Entity");
  }

  @Override
  protected Map<String, Object> partialObservation(PState state) {
    return Map.of("instances", state.get("instances"));
  }
}
