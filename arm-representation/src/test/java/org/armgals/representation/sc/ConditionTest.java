package org.armgals.representation.sc;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Activation;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The condition language of {@code cond}, evaluated without a script engine. */
class ConditionTest {
  private static final Configuration IN_A =
      new Configuration(new LinkedHashSet<>(List.of("P", "A")), Map.of());

  private static boolean holds(String cond, @Nullable String event, @Nullable Object data) {
    return Condition.parse(cond).holds(new Condition.Context(IN_A::isActive, event, data));
  }

  @Test
  void trueFalseAndInAreConstantsAndTheConfiguration() {
    assertThat(holds("true", null, null)).isTrue();
    assertThat(holds("false", null, null)).isFalse();
    assertThat(holds("In('A')", null, null)).isTrue();
    assertThat(holds("In(\"P\")", null, null)).isTrue();
    assertThat(holds("In('B')", null, null)).isFalse();
    assertThat(holds("In(A)", null, null)).isTrue();
  }

  @Test
  void theEventsNameComparesWithStrings() {
    assertThat(holds("_event.name == 'go'", "go", null)).isTrue();
    assertThat(holds("_event.name === \"go\"", "go", null)).isTrue();
    assertThat(holds("_event.name != 'go'", "stop", null)).isTrue();
    assertThat(holds("_event.name == 'go'", "stop", null)).isFalse();
    assertThat(holds("_event.name == 'go'", null, null)).isFalse();
  }

  @Test
  void theEventsDataFieldsCompareAsNumbersStringsBooleansAndNull() {
    Map<String, Object> data =
        Map.of("speed", 12, "mode", "eco", "on", true, "pos", Map.of("x", 2.5));
    assertThat(holds("_event.data.speed > 10", "e", data)).isTrue();
    assertThat(holds("_event.data.speed <= 11.5", "e", data)).isFalse();
    assertThat(holds("_event.data.speed == 12.0", "e", data)).isTrue();
    assertThat(holds("_event.data.pos.x >= 2.5", "e", data)).isTrue();
    assertThat(holds("_event.data.pos.x < -1", "e", data)).isFalse();
    assertThat(holds("_event.data.mode == 'eco'", "e", data)).isTrue();
    assertThat(holds("_event.data.mode < 'fast'", "e", data)).isTrue();
    assertThat(holds("_event.data.on", "e", data)).isTrue();
    assertThat(holds("_event.data.on == true", "e", data)).isTrue();
    assertThat(holds("_event.data.missing == null", "e", data)).isTrue();
    assertThat(holds("_event.data.missing > 1", "e", data)).isFalse();
    assertThat(holds("_event.data.mode > 1", "e", data)).isFalse();
    assertThat(holds("_event.data == 7", "e", 7)).isTrue();
    assertThat(holds("_event.data.speed == 12", "e", null)).isFalse();
  }

  @Test
  void booleanOperatorsCombineWithTheUsualPrecedence() {
    assertThat(holds("true || false && false", null, null)).isTrue();
    assertThat(holds("(true || false) && false", null, null)).isFalse();
    assertThat(holds("!In('B') && In('A')", null, null)).isTrue();
    assertThat(holds("!(In('A') || false)", null, null)).isFalse();
    assertThat(holds("!!true", null, null)).isTrue();
  }

  // W3C 449 (section B.2.3): "the SCXML processor MUST convert ECMAScript expressions used in
  // conditional expressions into their effective boolean value using the ToBoolean operator".
  @Test
  void aConditionsValueIsConvertedByToBoolean_w3c449() {
    Map<String, Object> data = new HashMap<>();
    data.put("zero", 0);
    data.put("nan", Double.NaN);
    data.put("empty", "");
    data.put("text", "no");
    data.put("nothing", null);
    data.put("object", Map.of());
    assertThat(holds("'foo'", null, null)).isTrue();
    assertThat(holds("''", null, null)).isFalse();
    assertThat(holds("0", null, null)).isFalse();
    assertThat(holds("-2.5", null, null)).isTrue();
    assertThat(holds("null", null, null)).isFalse();
    assertThat(holds("undefined", null, null)).isFalse();
    assertThat(holds("_event.data.zero", "e", data)).isFalse();
    assertThat(holds("_event.data.nan", "e", data)).isFalse();
    assertThat(holds("_event.data.empty", "e", data)).isFalse();
    assertThat(holds("_event.data.text", "e", data)).isTrue();
    assertThat(holds("_event.data.nothing", "e", data)).isFalse();
    assertThat(holds("_event.data.missing", "e", data)).isFalse();
    assertThat(holds("_event.data.object", "e", data)).isTrue();
    assertThat(holds("!_event.data.text", "e", data)).isFalse();
    assertThat(holds("!''", null, null)).isTrue();
  }

  // ECMAScript's == converts numbers, strings and booleans and takes null and undefined as equal;
  // === does not convert; a field the data does not have is undefined.
  @Test
  void equalityConvertsAsEcmascriptsEqualityOperatorsDo() {
    Map<String, Object> data = new HashMap<>();
    data.put("n", 1);
    data.put("s", "1");
    data.put("nothing", null);
    assertThat(holds("_event.data.s == 1", "e", data)).isTrue();
    assertThat(holds("_event.data.s === 1", "e", data)).isFalse();
    assertThat(holds("_event.data.n === 1.0", "e", data)).isTrue();
    assertThat(holds("_event.data.n == true", "e", data)).isTrue();
    assertThat(holds("_event.data.s != true", "e", data)).isFalse();
    assertThat(holds("'' == 0", null, null)).isTrue();
    assertThat(holds("'x' == 0", null, null)).isFalse();
    assertThat(holds("null == undefined", null, null)).isTrue();
    assertThat(holds("null === undefined", null, null)).isFalse();
    assertThat(holds("null == 0", null, null)).isFalse();
    assertThat(holds("_event.data.missing === undefined", "e", data)).isTrue();
    assertThat(holds("_event.data.missing === null", "e", data)).isFalse();
    assertThat(holds("_event.data.nothing === null", "e", data)).isTrue();
    assertThat(holds("_event.data === undefined", "e", null)).isTrue();
    assertThat(holds("_event.name === undefined", null, null)).isTrue();
    Map<String, Object> nan = Map.of("x", Double.NaN);
    assertThat(holds("_event.data.x == _event.data.x", "e", nan)).isFalse();
    assertThat(holds("_event.data.x != _event.data.x", "e", nan)).isTrue();
  }

  // ECMAScript's relational operators: two strings compare by code units, anything else as
  // numbers (null is 0, true is 1, undefined and a string that is no number are NaN, which
  // compares false).
  @Test
  void orderingComparesStringsAsStringsAndAnythingElseAsNumbers() {
    assertThat(holds("'10' < '9'", null, null)).isTrue();
    assertThat(holds("'10' < 9", null, null)).isFalse();
    assertThat(holds("' 12 ' > 11", null, null)).isTrue();
    assertThat(holds("'0x10' == 16", null, null)).isTrue();
    assertThat(holds("null < 1", null, null)).isTrue();
    assertThat(holds("null >= 0", null, null)).isTrue();
    assertThat(holds("true > 0", null, null)).isTrue();
    assertThat(holds("undefined < 1", null, null)).isFalse();
    assertThat(holds("undefined >= 1", null, null)).isFalse();
    assertThat(holds("'abc' <= 1", null, null)).isFalse();
    assertThat(holds("'abc' > 1", null, null)).isFalse();
    assertThat(holds("2 <= 2", null, null)).isTrue();
    assertThat(holds("3 <= 2", null, null)).isFalse();
    assertThat(holds("3 >= 2", null, null)).isTrue();
    assertThat(holds("_event.data > 9007199254740992", "e", 9007199254740993L)).isTrue();
  }

  // ECMAScript's && and || answer one of their operands, which a comparison may then read.
  @Test
  void andAndOrAnswerOneOfTheirOperands() {
    Map<String, Object> data = Map.of("mode", "fast");
    assertThat(holds("(_event.data.missing || 'eco') == 'eco'", "e", data)).isTrue();
    assertThat(holds("(_event.data.mode || 'eco') == 'eco'", "e", data)).isFalse();
    assertThat(holds("(0 && 'x') === 0", null, null)).isTrue();
    assertThat(holds("(1 && 'x') === 'x'", null, null)).isTrue();
  }

  @ParameterizedTest
  @ValueSource(
      strings = {
        "Var1 == 0",
        "x.y > 2",
        "_event.data.a + 1 > 2",
        "In('A'",
        "1 < 2 < 3",
        "'unterminated",
        "true false",
        "",
        "_event.origin == 'x'"
      })
  void anythingElseIsRefusedNamingTheConstruct(String cond) {
    assertThatThrownBy(() -> Condition.parse(cond))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("condition '" + cond + "'")
        .hasMessageContaining("is not supported");
  }

  // A chart whose conditions read the event: the event being processed in a dispatch.
  @Test
  void aChartsConditionsSeeTheEventsNameAndTheTriggersInputAsItsData() {
    // tag::speed[]
    Statechart chart =
        Statechart.of(
            ScDefinition.of("speed", ScNode.state("Slow"), ScNode.state("Fast"))
                .withTransitions(
                    ScTransition.on("up", "Slow", "go", "Fast")
                        .when("_event.name == 'go.fast' && _event.data.speed > 10"),
                    ScTransition.on("down", "Fast", "go", "Slow").when("_event.data.speed < 5")));
    Activation<Configuration> a = chart.activate(chart.initialState(), chart.transitions());
    assertThat(a.dispatch("go.slow", Map.of("speed", 20))).isEmpty(); // not go.fast
    assertThat(a.dispatch("go.fast", Map.of("speed", 8))).isEmpty(); // not above 10
    assertThat(a.dispatch("go.fast", Map.of("speed", 12)))
        .extracting(Step::behavior)
        .containsExactly("up");
    // end::speed[]
    assertThat(a.dispatch("go", Map.of("speed", 3))).extracting(Step::behavior).contains("down");
  }

  // The documented limit: a replay by name has no event, so _event.name is null there.
  @Test
  void aReplayByNameSeesNoEventName() {
    Statechart chart =
        Statechart.of(
            ScDefinition.of("named", ScNode.state("A"), ScNode.state("B"))
                .withTransitions(
                    ScTransition.on("t", "A", "go", "B").when("_event.name == 'go'"),
                    ScTransition.on("u", "B", "go", "A").when("_event.name != 'go'")));
    Activation<Configuration> model = chart.activate(chart.initialState(), chart.transitions());
    assertThatThrownBy(() -> model.apply("t", null))
        .isInstanceOf(org.armgals.representation.BehaviorNotApplicableException.class);
    model.reset(new Configuration(java.util.Set.of("B"), Map.of()));
    assertThat(model.apply("u", null).after().active()).containsExactly("A");
  }

  @Test
  void aNamedGuardWinsOverTheLanguageAndAnUnknownNameIsRefused() {
    Statechart chart =
        Statechart.of(
            ScDefinition.of("named", ScNode.state("A"), ScNode.state("B"))
                .withTransitions(ScTransition.on("t", "A", "e", "B").when("true")),
            Map.of("true", (c, in) -> false));
    Activation<Configuration> a = chart.activate(chart.initialState(), chart.transitions());
    assertThat(a.dispatch("e", null)).isEmpty();
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("unknown", ScNode.state("A"))
                        .withTransitions(ScTransition.on("t", "A", "e", "A").when("ready"))))
        .hasMessageContaining("'ready'")
        .hasMessageContaining("not a guard");
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("nowhere", ScNode.state("A"))
                        .withTransitions(ScTransition.on("t", "A", "e", "A").when("In('Z')"))))
        .hasMessageContaining("'Z'");
  }
}
