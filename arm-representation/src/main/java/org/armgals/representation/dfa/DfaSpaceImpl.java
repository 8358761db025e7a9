package org.armgals.representation.dfa;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import org.armgals.representation.Activation;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.internal.Observables;
import org.armgals.representation.internal.OrderedBehaviors;
import org.jspecify.annotations.Nullable;

/** The states of an automaton; see {@link DfaSpace}. */
final class DfaSpaceImpl implements DfaSpace {
  private final Map<String, DfaState> states;
  private final Set<String> observable;
  private final DfaState initial;
  private final OrderedBehaviors.Admission<DfaState> admission;
  private final Behaviors<DfaState> transitions;

  DfaSpaceImpl(Map<String, DfaState> states, String initial, List<String[]> transitions) {
    this.states = Collections.unmodifiableMap(new LinkedHashMap<>(states));
    this.initial = state(initial);
    Set<String> names = new LinkedHashSet<>();
    names.add(DfaState.STATE);
    for (DfaState s : states.values()) {
      names.addAll(s.outputs().keySet());
    }
    this.observable = Collections.unmodifiableSet(names);
    this.admission = new Determinism(this.states);
    Behaviors<DfaState> built = OrderedBehaviors.empty(admission);
    for (String[] t : transitions) {
      if (built.lookup(t[0]).isPresent()) {
        throw new IllegalArgumentException("transition id '" + t[0] + "' is declared twice");
      }
      built = built.with(new DfaTransition(t[0], state(t[1]), t[2], state(t[3])));
    }
    this.transitions = built;
  }

  /** A transition may join others when its states are the space's and it keeps it deterministic. */
  private record Determinism(Map<String, DfaState> states)
      implements OrderedBehaviors.Admission<DfaState> {
    @Override
    public void check(Behavior<DfaState> candidate, Collection<Behavior<DfaState>> others) {
      if (!(candidate instanceof DfaTransition t)) {
        throw new IllegalArgumentException(
            "behavior '"
                + candidate.name()
                + "' is a "
                + candidate.getClass().getName()
                + "; expected a DfaTransition");
      }
      for (DfaState s : List.of(t.source(), t.target())) {
        DfaState own = states.get(s.name());
        if (own == null) {
          throw new IllegalArgumentException(
              "transition '"
                  + t.id()
                  + "' names state '"
                  + s.name()
                  + "', which is not in the space; states: "
                  + states.keySet());
        }
        if (!own.equals(s)) {
          throw new IllegalArgumentException(
              "transition '"
                  + t.id()
                  + "' names state "
                  + s
                  + " of another space; this space's is "
                  + own);
        }
      }
      for (Behavior<DfaState> b : others) {
        DfaTransition o = (DfaTransition) b;
        if (o.source().equals(t.source()) && o.label().equals(t.label())) {
          throw new IllegalArgumentException(
              "transitions '"
                  + o.id()
                  + "' and '"
                  + t.id()
                  + "' both leave state '"
                  + t.source().name()
                  + "' on label '"
                  + t.label()
                  + "'; expected at most one transition per state and label");
        }
      }
    }
  }

  OrderedBehaviors.Admission<DfaState> admission() {
    return admission;
  }

  @Override
  public DfaState state(String name) {
    DfaState s = states.get(requireNonNull(name, "name"));
    if (s == null) {
      throw new IllegalArgumentException("no state '" + name + "'; states: " + states.keySet());
    }
    return s;
  }

  @Override
  public List<DfaState> states() {
    return List.copyOf(states.values());
  }

  @Override
  public Behaviors<DfaState> transitions() {
    return transitions;
  }

  @Override
  public DfaTransition transition(String id, String source, String label, String target) {
    return new DfaTransition(id, state(source), label, state(target));
  }

  @Override
  public DfaState initialState() {
    return initial;
  }

  @Override
  public boolean contains(DfaState state) {
    return requireNonNull(state, "state").equals(states.get(state.name()));
  }

  @Override
  public Set<DfaState> mapToState(Map<String, ?> observation, @Nullable DfaState current) {
    requireNonNull(observation, "observation");
    for (Map.Entry<String, ?> e : observation.entrySet()) {
      if (!observable.contains(e.getKey())) {
        throw new IllegalArgumentException(
            "observation names '"
                + e.getKey()
                + "', which no state has; expected one of "
                + observable);
      }
      Observables.check("observation of '" + e.getKey() + "'", e.getValue());
    }
    Object name = observation.get(DfaState.STATE);
    if (name != null && !states.containsKey(name.toString())) {
      throw new IllegalArgumentException(
          "observation names state '"
              + name
              + "', which is not in the space; states: "
              + states.keySet());
    }
    Set<DfaState> candidates = new LinkedHashSet<>();
    for (DfaState s : states.values()) {
      if (matches(s, observation)) {
        candidates.add(s);
      }
    }
    return Collections.unmodifiableSet(candidates);
  }

  private static boolean matches(DfaState s, Map<String, ?> observation) {
    for (Map.Entry<String, ?> e : observation.entrySet()) {
      Object seen = requireNonNull(e.getValue());
      if (e.getKey().equals(DfaState.STATE)) {
        if (!s.name().equals(seen.toString())) {
          return false;
        }
        continue;
      }
      Object own = s.outputs().get(e.getKey());
      if (own == null || !Objects.equals(own, Observables.coerce(seen, own.getClass()))) {
        return false;
      }
    }
    return true;
  }

  @Override
  public Activation<DfaState> activate(DfaState initial, Behaviors<DfaState> behaviors) {
    return new DfaActivation(this, initial, behaviors);
  }

  @Override
  public String toString() {
    return "DfaSpace" + states.keySet();
  }

  static List<DfaTransition> transitionsOf(Behaviors<DfaState> behaviors) {
    List<DfaTransition> all = new ArrayList<>();
    for (Behavior<DfaState> b : behaviors.all()) {
      all.add((DfaTransition) b);
    }
    return all;
  }
}
