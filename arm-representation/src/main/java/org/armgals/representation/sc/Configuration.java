package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.representation.State;

/**
 * The state of a statechart: the active states (leaves and every active ancestor, in document
 * order) and what each history pseudo-state remembers, since that decides where a later transition
 * leads.
 *
 * <p>{@link #observe()} gives {@code active} (a list of ids) and one {@code history.<id>} per
 * history pseudo-state (a list of ids, empty when nothing is remembered). A coarse observation
 * ({@link Statechart#observe(Configuration, int)}) gives only the active states down to a depth.
 *
 * @param active the ids of the active states
 * @param history for each history pseudo-state, the ids it remembers
 */
public record Configuration(Set<String> active, Map<String, List<String>> history)
    implements State {
  /** The observation key of the active states. */
  public static final String ACTIVE = "active";

  /** The prefix of the observation keys of history pseudo-states. */
  public static final String HISTORY = "history.";

  /** Copies the states and history, keeping their order. */
  public Configuration {
    active = Collections.unmodifiableSet(new LinkedHashSet<>(requireNonNull(active, "active")));
    Map<String, List<String>> copy = new LinkedHashMap<>();
    requireNonNull(history, "history").forEach((h, ids) -> copy.put(h, List.copyOf(ids)));
    history = Collections.unmodifiableMap(copy);
  }

  /** Whether the state {@code id} is active. */
  public boolean isActive(String id) {
    return active.contains(requireNonNull(id, "id"));
  }

  @Override
  public Map<String, Object> observe() {
    Map<String, Object> seen = new LinkedHashMap<>();
    seen.put(ACTIVE, List.copyOf(active));
    history.forEach((h, ids) -> seen.put(HISTORY + h, ids));
    return Collections.unmodifiableMap(seen);
  }

  @Override
  public String toString() {
    List<String> remembered = new ArrayList<>();
    history.forEach(
        (h, ids) -> {
          if (!ids.isEmpty()) {
            remembered.add(h + "=" + ids);
          }
        });
    return remembered.isEmpty() ? active.toString() : active + " " + remembered;
  }
}
