package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PSpace;
import org.armgals.representation.p.PState;

/**
 * The kind of a robot in the ARM kernel (paper figure 8: {@code AbstractRobot} is an {@code Entity}
 * whose structural meta-entity describes robots): a structural meta whose state space is what the
 * robots declare observable ({@link AbstractRobot#observe()}, the procedural representation: one
 * field per observed value) and whose behaviors are the reified side of what a robot does. {@link
 * #CYCLE} is one synchronous cycle: its input is the cycle's observation, and the state after it is
 * that observation, so a behavioral meta's model replays a robot's action events exactly as it
 * integrates its state events. The other behaviors are the paper's adaptation method requests
 * ({@code setScheduling}, {@code changeModule}, and adding or removing schemas and connectors): a
 * meta asks for one with {@link #request}, the robot applies the change to its program at its
 * adaptation point, and the next cycle's observation shows it (its {@code program} version).
 *
 * <p>Threading: {@link #define} on any thread; the kind it returns is the kernel's.
 */
public final class RobotKind {

  /** One cycle; its input is the cycle's observation. */
  public static final String CYCLE = "cycle";

  private RobotKind() {}

  /**
   * A new kind of robot in {@code kernel}, whose robots observe the fields of {@code initial} (one
   * robot's {@link AbstractRobot#observation()} before its first cycle, typically).
   *
   * @throws IllegalArgumentException a blank or taken name
   */
  public static StructuralMeta<PState> define(Kernel kernel, String name, PState initial) {
    requireNonNull(kernel, "kernel");
    requireNonNull(name, "name");
    requireNonNull(initial, "initial");
    PSpace space = PSpace.of(initial);
    PMethod cycle = PMethod.of(CYCLE, (s, in) -> observed(name, in));
    PMethod[] methods = new PMethod[1 + RobotAdaptations.NAMES.size()];
    methods[0] = cycle;
    int i = 1;
    for (String adaptation : RobotAdaptations.NAMES) {
      methods[i++] = PMethod.of(adaptation, (s, in) -> s);
    }
    return kernel.newStructuralMeta(name, space, space.methods(methods));
  }

  /**
   * The kernel's adaptation request for {@code change}: the behavior named after it ({@code
   * setScheduling}, {@code changeModule}, ...), with the change as its input. A robot's meta sends
   * it with its {@link org.armgals.kernel.spi.MetaContext#adapt}; versions, acknowledgements and
   * damping are the kernel's.
   */
  public static org.armgals.kernel.Adaptation request(Adaptation change) {
    requireNonNull(change, "change");
    return new org.armgals.kernel.Adaptation.ApplyBehavior(RobotAdaptations.name(change), change);
  }

  /**
   * The kernel's request for a {@code changeModule} by name and parameters: the robot builds the
   * replacement from its catalog ({@link AbstractRobot#module}). Unlike {@link #request}, which
   * carries the module itself, it holds only simple values, so a meta in another runtime can send
   * it.
   *
   * @param module the name of the module to replace
   * @param parameters its new parameters: strings, booleans, boxed numbers, lists of those
   */
  public static org.armgals.kernel.Adaptation changeModule(
      String module, Map<String, Object> parameters) {
    requireNonNull(module, "module");
    requireNonNull(parameters, "parameters");
    return new org.armgals.kernel.Adaptation.ApplyBehavior(
        RobotAdaptations.CHANGE_MODULE, Map.of(MODULE, module, PARAMETERS, Map.copyOf(parameters)));
  }

  /** The key of the module's name in a {@link #changeModule(String, Map)} request. */
  static final String MODULE = "module";

  /** The key of the parameters in a {@link #changeModule(String, Map)} request. */
  static final String PARAMETERS = "parameters";

  private static PState observed(String kind, Object input) {
    if (!(input instanceof Map<?, ?> fields)) {
      throw new IllegalArgumentException(
          "the input of " + kind + "." + CYCLE + " must be the cycle's observation, was " + input);
    }
    @SuppressWarnings("unchecked")
    Map<String, Object> typed = (Map<String, Object>) fields;
    return new PState(typed);
  }
}
