package org.armgals.representation.dfa;

import static java.util.Objects.requireNonNull;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.representation.State;
import org.armgals.representation.internal.Observables;

/**
 * A state of an automaton: a name, unique in its space, and outputs (properties an observer can see
 * of the state, which several states may share, such as {@code moving = true}).
 *
 * <p>{@link #observe()} is {@code state = name} and the outputs; an observation that gives only
 * some outputs stands for every state that has them.
 *
 * @param name the state's name
 * @param outputs the state's outputs, by name; {@code "state"} is reserved
 */
public record DfaState(String name, Map<String, Object> outputs) implements State {
  /** The name under which {@link #observe()} gives the state's name. */
  public static final String STATE = "state";

  /**
   * Checks the name and copies the outputs, keeping their order.
   *
   * @throws IllegalArgumentException if the name is blank, an output is named {@value #STATE}, or
   *     an output is not observable
   */
  public DfaState {
    requireNonNull(name, "name");
    if (name.isBlank()) {
      throw new IllegalArgumentException("state name '" + name + "' is blank; expected a name");
    }
    requireNonNull(outputs, "outputs");
    Map<String, Object> copy = new LinkedHashMap<>();
    outputs.forEach(
        (key, value) -> {
          requireNonNull(key, "output name");
          if (key.equals(STATE)) {
            throw new IllegalArgumentException(
                "state '" + name + "' has an output named '" + STATE + "', which is reserved");
          }
          copy.put(key, Observables.check("output '" + key + "' of state '" + name + "'", value));
        });
    outputs = Collections.unmodifiableMap(copy);
  }

  /** A state without outputs. */
  public static DfaState named(String name) {
    return new DfaState(name, Map.of());
  }

  @Override
  public Map<String, Object> observe() {
    Map<String, Object> seen = new LinkedHashMap<>();
    seen.put(STATE, name);
    seen.putAll(outputs);
    return Collections.unmodifiableMap(seen);
  }

  @Override
  public String toString() {
    return outputs.isEmpty() ? name : name + outputs;
  }
}
