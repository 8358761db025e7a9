package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.Arrays;
import java.util.List;
import org.jspecify.annotations.Nullable;

/**
 * A transition of a statechart definition, the behavior of the SC family once bound to a chart
 * ({@link Statechart#bind}).
 *
 * <p>It is enabled when its source is active, one of its event descriptors matches the event (a
 * descriptor {@code a.b} matches {@code a.b} and {@code a.b.c}; {@code *} matches any event; no
 * descriptor at all makes an eventless transition, taken as soon as its guard holds) and its guard
 * holds. Without targets it exits and enters nothing. An external transition exits its source; an
 * internal one whose targets are all inside its compound source does not.
 *
 * @param id unique in its behaviors; what an action event carries
 * @param source the id of the state it leaves
 * @param events event descriptors; empty for an eventless transition
 * @param cond the name of a {@link Guard}, or a condition of the condition language ({@code
 *     In('id')}, {@code true}, comparisons of {@code _event.name} and {@code _event.data} fields:
 *     docs/representations.md); null when always enabled
 * @param targets ids of the states it enters
 * @param internal whether it is internal (SCXML {@code type="internal"})
 * @param actions its own actions, run between the exits and the entries
 */
public record ScTransition(
    String id,
    String source,
    List<String> events,
    @Nullable String cond,
    List<String> targets,
    boolean internal,
    List<ScAction> actions) {

  /** Checks the names and copies the lists. */
  public ScTransition {
    ScNames.requireName(id, "transition id");
    ScNames.requireName(source, "source of transition '" + id + "'");
    events = ScNames.requireNames(events, "event of transition '" + id + "'");
    if (cond != null && cond.isBlank()) {
      throw new IllegalArgumentException(
          "cond of transition '" + id + "' is blank; expected a guard name or null");
    }
    targets = ScNames.requireNames(targets, "target of transition '" + id + "'");
    actions = List.copyOf(requireNonNull(actions, "actions"));
  }

  /** An external transition on {@code event} (one descriptor, or several separated by spaces). */
  public static ScTransition on(String id, String source, String event, String... targets) {
    List<String> events = List.of(requireNonNull(event, "event").strip().split("\\s+"));
    return new ScTransition(id, source, events, null, Arrays.asList(targets), false, List.of());
  }

  /** An external eventless transition. */
  public static ScTransition eventless(String id, String source, String... targets) {
    return new ScTransition(id, source, List.of(), null, Arrays.asList(targets), false, List.of());
  }

  /** This transition guarded by {@code cond}. */
  public ScTransition when(String cond) {
    return new ScTransition(
        id, source, events, requireNonNull(cond, "cond"), targets, internal, actions);
  }

  /** This transition, internal. */
  public ScTransition asInternal() {
    return new ScTransition(id, source, events, cond, targets, true, actions);
  }

  /** This transition with {@code actions}. */
  public ScTransition doing(ScAction... actions) {
    return new ScTransition(id, source, events, cond, targets, internal, Arrays.asList(actions));
  }
}
