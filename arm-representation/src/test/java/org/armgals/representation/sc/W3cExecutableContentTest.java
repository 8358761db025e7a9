package org.armgals.representation.sc;

import static org.armgals.representation.sc.ScAction.raise;
import static org.armgals.representation.sc.ScAction.run;
import static org.armgals.representation.sc.ScAction.send;
import static org.armgals.representation.sc.ScAction.sendExpr;
import static org.armgals.representation.sc.ScAction.when;
import static org.armgals.representation.sc.W3cAlgorithmTest.atomic;
import static org.armgals.representation.sc.W3cAlgorithmTest.chart;
import static org.armgals.representation.sc.W3cAlgorithmTest.passesAtStart;
import static org.armgals.representation.sc.W3cAlgorithmTest.start;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Activation;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.RepresentationException;
import org.armgals.representation.Step;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The executable content the subset adds to {@code <raise>}: {@code <send>} to the chart itself
 * without delay, {@code <if>}, and a final state's {@code <donedata>}, each rule named after the
 * recommendation's assertion it checks. The charts under {@code w3c/} were written for armgals from
 * the recommendation's text and what the W3C implementation report tests of those numbers check;
 * each ends in the top-level final state {@code pass} when the rule holds.
 */
class W3cExecutableContentTest {

  private static Statechart of(ScDefinition d) {
    Statechart chart = Statechart.of(d);
    assertThat(Scxml.read(Scxml.write(d))).isEqualTo(d);
    return chart;
  }

  // C.1, 193: "If neither the 'target' nor the 'targetexpr' attribute is specified, the SCXML
  // Processor MUST add the event to the external event queue of the sending session" -- taken
  // after the macrostep, its internal events first; 198, 200: the SCXML event I/O processor is the
  // default and may be named.
  @Test
  void aSendWithoutTargetGoesToTheExternalQueueTakenAfterTheMacrostep_w3c193_w3c200() {
    passesAtStart("test193");
  }

  // C.1, 189: "If the target is the special term '#_internal', the Processor MUST add the event
  // to the internal event queue of the sending session".
  @Test
  void aSendToInternalGoesToTheInternalQueue_w3c189() {
    passesAtStart("test189");
  }

  // 3.13, 423: after a macrostep the processor takes the next external event and runs the
  // transitions it enables as a microstep, then completes that macrostep before the next one.
  @Test
  void eachSentEventIsTakenAsAMacrostepOfItsOwnInOrder_w3c423() {
    passesAtStart("test423");
  }

  // 3.13, 423: events are removed from the external queue "until it finds one that enables a
  // non-empty optimal transition set": a sent event that enables nothing is dropped.
  @Test
  void aSentEventThatEnablesNothingIsDropped_w3c423() {
    Statechart chart =
        of(
            ScDefinition.of(
                    "drop",
                    ScNode.state("A").onEntry(send("nothing"), send("go")),
                    ScNode.finalState("pass"))
                .withTransitions(ScTransition.on("go", "A", "go", "pass")));
    assertThat(chart.initialState().active()).containsExactly("pass");
  }

  // A dispatch takes the trigger's macrostep, then those of the events the chart sent itself,
  // and answers every microstep in order; the actions of the whole dispatch are the steps'.
  @Test
  void aDispatchTakesTheEventsTheChartSentItselfAfterTheTriggersMacrostep() {
    Statechart chart =
        of(
            ScDefinition.of("relay", ScNode.state("A"), ScNode.state("B"), ScNode.state("C"))
                .withTransitions(
                    ScTransition.on("ab", "A", "go", "B").doing(send("next"), run("first")),
                    ScTransition.eventless("bc", "B", "C").when("_event.name == 'next'")));
    Activation<Configuration> a = start(chart);
    List<Step<Configuration>> steps = a.dispatch("go", null);
    assertThat(steps).extracting(Step::behavior).containsExactly("ab", "bc");
    assertThat(steps.get(0).result()).isEqualTo(List.of("first"));
    assertThat(a.state().active()).containsExactly("C");
  }

  // 5.10, 318: "The SCXML Processor MUST bind the _event variable when an event is pulled off the
  // internal or external event queue to be processed": a sent event's conditions see its name,
  // and what it carries as its data; an event that carries nothing has the trigger's input.
  @Test
  void aSentEventsConditionsSeeItsNameAndData_w3c318() {
    Statechart chart =
        of(
            ScDefinition.of(
                    "data",
                    ScNode.state("A"),
                    ScNode.state("B"),
                    ScNode.state("C"),
                    ScNode.finalState("fail"))
                .withTransitions(
                    ScTransition.on("ab", "A", "go", "B")
                        .doing(send("plain"), send("carrying").with(ScData.expr("'own'"))),
                    ScTransition.on("plain", "B", "plain", "C")
                        .when("_event.name == 'plain' && _event.data.speed == 3"),
                    ScTransition.on("failB", "B", "*", "fail"),
                    ScTransition.on("own", "C", "carrying", "A").when("_event.data === 'own'"),
                    ScTransition.on("failC", "C", "*", "fail")));
    Activation<Configuration> a = start(chart);
    assertThat(a.dispatch("go", Map.of("speed", 3)))
        .extracting(Step::behavior)
        .containsExactly("ab", "plain", "own");
    assertThat(a.state().active()).containsExactly("A");
  }

  // 6.2, 176, and B.2, 560: the params of a send are evaluated and delivered as the event's data,
  // each key a property of _event.data.
  @Test
  void theParamsOfASendAreTheEventsData_w3c176_w3c560() {
    passesAtStart("test560");
  }

  // 6.2, 186: "The Processor MUST evaluate all arguments to send when the send element is
  // evaluated, and not when the message is actually dispatched".
  @Test
  void theArgumentsOfASendAreEvaluatedWhenTheSendRuns_w3c186() {
    passesAtStart("test186");
  }

  // 6.2, 179: "The SCXML Processor MUST evaluate the content element when the parent send element
  // is evaluated and pass the resulting data unmodified".
  @Test
  void theContentOfASendIsTheEventsData_w3c179() {
    passesAtStart("test179");
  }

  // B.2, 562: content that is neither key-value pairs, JSON nor XML is "a space-normalized string
  // literal".
  @Test
  void contentThatIsNotJsonIsASpaceNormalizedString_w3c562() {
    passesAtStart("test562");
  }

  // B.2, 578: content that can be interpreted as JSON gives "the corresponding ECMAScript
  // structure(s)".
  @Test
  void contentThatIsJsonIsTheStructureItDenotes_w3c578() {
    passesAtStart("test578");
  }

  // 6.2, 172: "If 'eventexpr' is present, the SCXML Processor MUST evaluate it when the parent
  // send element is evaluated and treat the result as if it had been entered as the value of
  // 'event'".
  @Test
  void eventexprGivesTheEventsNameWhenTheSendRuns_w3c172() {
    Statechart chart =
        of(
            ScDefinition.of("named", ScNode.state("A"), ScNode.state("B"), ScNode.state("C"))
                .withTransitions(
                    ScTransition.on("ab", "A", "go", "B").doing(sendExpr("_event.data.next")),
                    ScTransition.on("bc", "B", "step.two", "C")));
    Activation<Configuration> a = start(chart);
    a.dispatch("go", Map.of("next", "step.two"));
    assertThat(a.state().active()).containsExactly("C");
  }

  // 6.2, 553, and 4.9, 159: when the evaluation of a send's arguments fails (here eventexpr gives
  // no event name), the message is discarded, error.execution goes on the internal queue, and
  // "the processor MUST NOT process the remaining elements of the block".
  @ParameterizedTest
  @ValueSource(strings = {"two words", ""})
  void aSendWhoseEventexprNamesNoEventRaisesAnErrorAndEndsItsBlock_w3c553_w3c159(String name) {
    Statechart chart =
        of(
            ScDefinition.of(
                    "error",
                    ScNode.state("A"),
                    ScNode.state("B"),
                    ScNode.state("C"),
                    ScNode.finalState("fail"))
                .withTransitions(
                    ScTransition.on("ab", "A", "go", "B")
                        .doing(sendExpr("_event.data.name"), raise("after"), run("after")),
                    ScTransition.on("error", "B", "error.execution", "C"),
                    ScTransition.on("failB", "B", "*", "fail"),
                    ScTransition.on("failC", "C", "*", "fail")));
    Activation<Configuration> a = start(chart);
    List<Step<Configuration>> steps = a.dispatch("go", Map.of("name", name));
    assertThat(steps).extracting(Step::behavior).containsExactly("ab", "error");
    assertThat(steps.get(0).result()).isEqualTo(List.of());
    assertThat(a.state().active()).containsExactly("C");
    // A map is no event name either; a number is, as ECMAScript writes it.
    a.reset(chart.initialState());
    a.dispatch("go", Map.of("name", Map.of()));
    assertThat(a.state().active()).containsExactly("C");
  }

  @Test
  void anEventexprValueIsWrittenAsEcmascriptWritesIt() {
    Statechart chart =
        of(
            ScDefinition.of("numbers", ScNode.state("A"), ScNode.state("B"), ScNode.state("C"))
                .withTransitions(
                    ScTransition.on("ab", "A", "go", "B").doing(sendExpr("_event.data.n")),
                    ScTransition.on("bc", "B", "2.5", "C")));
    Activation<Configuration> a = start(chart);
    a.dispatch("go", Map.of("n", 2.50));
    assertThat(a.state().active()).containsExactly("C");
  }

  // Appendix D: the recommendation's main event loop never ends on its own if the chart keeps
  // sending itself events; a dispatch that does not come to rest is reported, all or nothing.
  @Test
  void aDispatchThatKeepsSendingItselfEventsIsReportedAndChangesNothing() {
    Statechart chart =
        of(
            ScDefinition.of("ping", ScNode.state("A"), ScNode.state("B"))
                .withTransitions(
                    ScTransition.on("start", "A", "go", "B").doing(send("ping")),
                    ScTransition.on("again", "B", "ping", "B").doing(send("ping"))));
    Activation<Configuration> a = start(chart);
    assertThatThrownBy(() -> a.dispatch("go", null))
        .isInstanceOf(RepresentationException.class)
        .hasMessageContaining("microsteps");
    assertThat(a.state()).isEqualTo(chart.initialState());
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("pingAtStart", ScNode.state("A").onEntry(send("ping")))
                        .withTransitions(ScTransition.on("again", "A", "ping", "A"))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("does not come to rest");
  }

  // 4.3, 147: "When the if element is executed, the SCXML processor MUST execute the first
  // partition in document order that is defined by a tag whose 'cond' attribute evaluates to
  // true, if there is one".
  @Test
  void anIfRunsTheFirstPartitionWhoseCondIsTrue_w3c147() {
    passesAtStart("test147");
  }

  // 4.3, 148: "if no 'cond' attribute evaluates to true, the SCXML Processor must execute the
  // partition defined by the else tag, if there is one".
  @Test
  void anIfRunsItsElseWhenNoCondIsTrue_w3c148() {
    passesAtStart("test148");
  }

  // 4.3, 149: "if no 'cond' attribute evaluates to true and there is no else element, the SCXML
  // processor must not evaluate any executable content within the element".
  @Test
  void anIfWithoutElseRunsNothingWhenNoCondIsTrue_w3c149() {
    passesAtStart("test149");
  }

  // 3.13, 411: "To enter a state, the SCXML Processor MUST add the state to the active state's
  // list. Then it MUST execute the executable content in the state's onentry handler" -- which sees
  // the state, and not yet its children.
  @Test
  void onentryContentSeesTheStateEnteredAndNotYetItsChildren_w3c411() {
    passesAtStart("test411");
  }

  // 3.13, 409: to exit a state the processor runs its onexit, and "Finally ... MUST remove the
  // state from the active state's list" -- so its onexit sees it, and no longer its child.
  @Test
  void onexitContentSeesTheStateExitedAndNoLongerItsChildren_w3c409() {
    passesAtStart("test409");
  }

  // Actions named in a branch are the step's actions only when the branch runs; branches nest.
  @Test
  void theActionsOfABranchAreRunOnlyWhenItsCondHolds() {
    Statechart chart =
        of(
            ScDefinition.of("lamp", ScNode.state("Off"), ScNode.state("On"))
                .withTransitions(
                    ScTransition.on("on", "Off", "press", "On")
                        .doing(
                            when("_event.data.level > 5", run("bright"))
                                .orElseIf(
                                    "_event.data.level > 0",
                                    run("dim"),
                                    when("_event.data.level == 1", run("dimmest")))
                                .orElse(run("dark")),
                            run("done"))));
    assertThat(start(chart).dispatch("press", Map.of("level", 9)).get(0).result())
        .isEqualTo(List.of("bright", "done"));
    assertThat(start(chart).dispatch("press", Map.of("level", 1)).get(0).result())
        .isEqualTo(List.of("dim", "dimmest", "done"));
    assertThat(start(chart).dispatch("press", Map.of()).get(0).result())
        .isEqualTo(List.of("dark", "done"));
  }

  // 5.5, 294: "In cases where the SCXML Processor generates a 'done' event upon entry into the
  // final state, it MUST evaluate the donedata elements param or content children and place the
  // resulting data in the _event.data field".
  @Test
  void theDoneDataOfAFinalStateIsTheDataOfItsDoneEvent_w3c294() {
    passesAtStart("test294");
  }

  // 5.6, 527: "if the 'expr' value expression is present, the Processor MUST evaluate it and use
  // the result as the output of the content element"; 529: "If the 'expr' attribute is not
  // present, the Processor MUST use the children of content as the output".
  @Test
  void contentIsItsExprElseItsChildren_w3c527_w3c529() {
    passesAtStart("test527");
  }

  // 3.7, 570: the done event of a parallel state whose regions are all final carries no done data
  // (a final state's donedata goes with its parent's done event): it has the trigger's input.
  @Test
  void theDoneEventOfAParallelStateCarriesNoDoneData_w3c570() {
    Statechart chart =
        of(
            ScDefinition.of(
                    "join",
                    ScNode.parallel(
                        "P",
                        ScNode.state(
                            "R1",
                            ScNode.state("a1"),
                            ScNode.finalState("f1").withDoneData(ScData.expr("'r1'"))),
                        ScNode.state("R2", ScNode.finalState("f2"))),
                    ScNode.state("R1done"),
                    ScNode.state("Pdone"))
                .withTransitions(
                    ScTransition.on("a1", "a1", "go", "f1"),
                    ScTransition.on("r1", "P", "done.state.R1", "R1done")
                        .when("_event.data === 'r1'"),
                    ScTransition.on("p", "P", "done.state.P", "Pdone")
                        .when("_event.data.speed == 4")));
    Activation<Configuration> a = start(chart);
    // done.state.R2 at start; done.state.R1 then done.state.P on go: R1's is taken first.
    assertThat(a.dispatch("go", Map.of("speed", 4))).extracting(Step::behavior).contains("r1");
    assertThat(a.state().active()).containsExactly("R1done");

    Statechart onlyParallel =
        of(
            new ScDefinition(
                "joinP",
                List.of(),
                chart.definition().states(),
                List.of(
                    ScTransition.on("a1", "a1", "go", "f1"),
                    ScTransition.on("p", "P", "done.state.P", "Pdone")
                        .when("_event.data.speed == 4"))));
    Activation<Configuration> b = start(onlyParallel);
    b.dispatch("go", Map.of("speed", 4));
    assertThat(b.state().active()).containsExactly("Pdone");
  }

  // Every expression's In() must name a state of the chart, in executable content as in a
  // transition's condition.
  @Test
  void anInInExecutableContentMustNameAStateOfTheChart() {
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("typo", ScNode.state("A").onEntry(when("In('Z')", run("x"))))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'Z'")
        .hasMessageContaining("state 'A'");
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of(
                        "typo2",
                        ScNode.state("A"),
                        ScNode.finalState("F").withDoneData(ScData.expr("In('Y')")))))
        .hasMessageContaining("'Y'")
        .hasMessageContaining("state 'F'");
  }

  // A model replaying an entity's steps by name ends where the entity did, sent events included.
  @ParameterizedTest
  @ValueSource(strings = {"test189", "test193", "test423", "test409", "test411"})
  void replayingTheStepsByNameGivesTheSameConfigurations(String test) {
    Statechart chart = waiting(test);
    Activation<Configuration> entity = start(chart);
    Activation<Configuration> model = start(chart);
    for (Step<Configuration> step : entity.dispatch("begin", Map.of())) {
      model.apply(step.behavior(), Map.of());
      assertThat(model.state()).isEqualTo(step.after());
    }
    assertThat(atomic(chart, model.state())).containsExactly("pass");
  }

  // A replay names transitions and passes the trigger's input: a condition on the data an event
  // carries of its own cannot be decided there, and the step is not applicable (a model then
  // resynchronizes from a state event, as for a condition on _event.name).
  @Test
  void aConditionOnTheDataOfASentEventIsNotDecidedInAReplay() {
    Statechart chart = waiting("test186");
    Activation<Configuration> entity = start(chart);
    Activation<Configuration> model = start(chart);
    List<Step<Configuration>> steps = entity.dispatch("begin", Map.of());
    assertThat(atomic(chart, entity.state())).containsExactly("pass");
    for (Step<Configuration> step : steps.subList(0, steps.size() - 1)) {
      model.apply(step.behavior(), Map.of());
    }
    String last = steps.get(steps.size() - 1).behavior();
    assertThatThrownBy(() -> model.apply(last, Map.of()))
        .isInstanceOf(BehaviorNotApplicableException.class);
  }

  /** Chart {@code test} waiting for {@code begin} before it enters its first state. */
  private static Statechart waiting(String test) {
    ScDefinition d = chart(test).definition();
    // The same chart, waiting for 'begin' before its first state.
    ScDefinition waiting =
        new ScDefinition(
            d.name(),
            List.of(),
            concat(ScNode.state("before"), d.states()),
            concat(ScTransition.on("begin", "before", "begin", "s0"), d.transitions()));
    return Statechart.of(waiting);
  }

  private static <T> List<T> concat(T first, List<T> rest) {
    List<T> all = new ArrayList<>();
    all.add(first);
    all.addAll(rest);
    return all;
  }
}
