package org.armgals.representation.p;

import java.util.List;
import java.util.Map;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.RepresentationContract;
import org.armgals.representation.StateSpace;

class PContractTest extends RepresentationContract<PState> {
  /** The fields of a counter entity. */
  record Counter(int count, String label) {}

  static final PSpace SPACE = PSpace.ofRecord(new Counter(0, "c"));

  static final PMethod INCREMENT =
      PMethod.returning(
          "increment",
          (s, in) -> {
            int next = (Integer) s.get("count") + 1;
            return new PMethod.Outcome(s.with("count", next), next);
          });
  static final PMethod DECREMENT =
      PMethod.of("decrement", (s, in) -> s.with("count", (Integer) s.get("count") - 1))
          .when((s, in) -> (Integer) s.get("count") > 0);
  static final PMethod RENAME =
      PMethod.of("rename", (s, in) -> s.with("label", String.valueOf(in)));

  @Override
  protected StateSpace<PState> space() {
    return SPACE;
  }

  @Override
  protected Behaviors<PState> behaviors() {
    return SPACE.methods(INCREMENT, DECREMENT, RENAME);
  }

  @Override
  protected Trigger applicable() {
    return new Trigger("increment", null);
  }

  @Override
  protected String inapplicable() {
    return "decrement";
  }

  @Override
  protected List<Trigger> triggers() {
    return List.of(
        new Trigger("increment", null),
        new Trigger("increment", null),
        new Trigger("rename", "counter"),
        new Trigger("decrement", null),
        new Trigger("decrement", null),
        new Trigger("decrement", null));
  }

  @Override
  protected String idleTrigger() {
    return "decrement";
  }

  @Override
  protected Behavior<PState> extra() {
    return EXTRA;
  }

  private static final PMethod EXTRA =
      PMethod.of("extra", (s, in) -> s.with("count", (Integer) s.get("count") * 2 + 1));

  @Override
  protected PState outside() {
    return new PState(Map.of("count", "not a number", "label", "c"));
  }

  @Override
  protected Map<String, Object> partialObservation(PState state) {
    return Map.of("count", state.get("count"));
  }
}
