package org.armgals.representation.sc;

import static org.armgals.representation.sc.ScAction.raise;
import static org.armgals.representation.sc.ScAction.run;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Map;
import org.armgals.representation.Activation;
import org.armgals.representation.RepresentationException;
import org.armgals.representation.Step;
import org.junit.jupiter.api.Test;

class StatechartTest {

  private static Activation<Configuration> start(Statechart chart) {
    return chart.activate(chart.initialState(), chart.transitions());
  }

  private static Activation<Configuration> start(ScDefinition definition) {
    return start(Statechart.of(definition));
  }

  private static List<String> behaviors(List<Step<Configuration>> steps) {
    return steps.stream().map(Step::behavior).toList();
  }

  // A compound state S with children A and B, each with entry and exit actions.
  private static ScDefinition nested(ScTransition t) {
    return ScDefinition.of(
            "nested",
            ScNode.state(
                    "S",
                    ScNode.state("A").onEntry(run("enterA")).onExit(run("exitA")),
                    ScNode.state("B").onEntry(run("enterB")).onExit(run("exitB")))
                .onEntry(run("enterS"))
                .onExit(run("exitS")))
        .withTransitions(t);
  }

  @Test
  void theInitialEntryRunsEntryActionsFromTheOutside() {
    Statechart chart = Statechart.of(nested(ScTransition.on("t", "S", "e", "B")));
    assertThat(chart.initialActions()).containsExactly("enterS", "enterA");
    assertThat(chart.initialState().active()).containsExactly("S", "A");
  }

  @Test
  void anExternalTransitionExitsAndReentersItsSource() {
    Activation<Configuration> a =
        start(nested(ScTransition.on("t", "S", "e", "B").doing(run("act"))));
    List<Step<Configuration>> steps = a.dispatch("e", null);
    assertThat(steps)
        .singleElement()
        .extracting(Step::result)
        .isEqualTo(List.of("exitA", "exitS", "act", "enterS", "enterB"));
    assertThat(a.state().active()).containsExactly("S", "B");
  }

  @Test
  void anInternalTransitionDoesNotExitItsCompoundSource() {
    Activation<Configuration> a =
        start(nested(ScTransition.on("t", "S", "e", "B").asInternal().doing(run("act"))));
    assertThat(a.dispatch("e", null))
        .singleElement()
        .extracting(Step::result)
        .isEqualTo(List.of("exitA", "act", "enterB"));
  }

  @Test
  void aTargetlessTransitionRunsItsActionsOnlyAndKeepsTheConfiguration() {
    Activation<Configuration> a = start(nested(ScTransition.on("t", "A", "e").doing(run("tick"))));
    Configuration before = a.state();
    List<Step<Configuration>> steps = a.dispatch("e", null);
    assertThat(steps).singleElement().satisfies(s -> assertThat(s.changed()).isFalse());
    assertThat(steps.get(0).result()).isEqualTo(List.of("tick"));
    assertThat(a.state()).isEqualTo(before);
  }

  // P holds X (X1, X2) and Y, with a shallow and a deep history; Out is outside.
  private static final ScDefinition HISTORY =
      ScDefinition.of(
              "history",
              ScNode.state(
                  "P",
                  ScNode.history("HS", false),
                  ScNode.history("HD", true),
                  ScNode.state("X", ScNode.state("X1"), ScNode.state("X2")),
                  ScNode.state("Y")),
              ScNode.state("Out"))
          .withInitial("Out")
          .withTransitions(
              ScTransition.on("enter", "Out", "enter", "P"),
              ScTransition.on("leave", "P", "leave", "Out"),
              ScTransition.on("shallow", "Out", "shallow", "HS"),
              ScTransition.on("deep", "Out", "deep", "HD"),
              ScTransition.on("next", "X1", "next", "X2"));

  @Test
  void aHistoryWithNothingRememberedLeadsToItsParentsInitialState() {
    Activation<Configuration> a = start(HISTORY);
    a.dispatch("deep", null);
    assertThat(a.state().active()).containsExactly("P", "X", "X1");
  }

  @Test
  void shallowHistoryRestoresTheChildAndDeepHistoryTheLeaf() {
    Activation<Configuration> a = start(HISTORY);
    a.dispatch("enter", null);
    a.dispatch("next", null);
    a.dispatch("leave", null);
    assertThat(a.state().history())
        .containsEntry("HS", List.of("X"))
        .containsEntry("HD", List.of("X2"));

    a.dispatch("shallow", null);
    assertThat(a.state().active()).containsExactly("P", "X", "X1");

    a.dispatch("next", null);
    a.dispatch("leave", null);
    a.dispatch("deep", null);
    assertThat(a.state().active()).containsExactly("P", "X", "X2");
  }

  @Test
  void historyIsPartOfTheStateSoThatAModelResetFromAnObservationRestoresTheSame() {
    Statechart chart = Statechart.of(HISTORY);
    Activation<Configuration> entity = start(chart);
    entity.dispatch("enter", null);
    entity.dispatch("next", null);
    entity.dispatch("leave", null);
    Activation<Configuration> model = start(chart);
    model.reset(chart.mapToState(entity.state().observe(), null).iterator().next());
    entity.dispatch("deep", null);
    model.dispatch("deep", null);
    assertThat(model.state()).isEqualTo(entity.state());
    assertThat(entity.state().active()).contains("X2");
  }

  // Two regions that both react to e.
  private static final ScDefinition REGIONS =
      ScDefinition.of(
              "regions",
              ScNode.parallel(
                  "Par",
                  ScNode.state("R1", ScNode.state("a1"), ScNode.state("b1")),
                  ScNode.state("R2", ScNode.state("a2"), ScNode.state("b2"))))
          .withTransitions(
              ScTransition.on("t1", "a1", "e", "b1").doing(run("one")),
              ScTransition.on("t2", "a2", "e", "b2").doing(run("two")),
              ScTransition.on("t3", "a2", "f", "b2").when("In(b1)"));

  @Test
  void oneEventTakesATransitionInEachOrthogonalRegionAsOneMicrostep() {
    Activation<Configuration> a = start(REGIONS);
    assertThat(a.state().active()).containsExactly("Par", "R1", "a1", "R2", "a2");
    List<Step<Configuration>> steps = a.dispatch("e", null);
    assertThat(behaviors(steps)).containsExactly("t1 t2");
    assertThat(steps.get(0).result()).isEqualTo(List.of("one", "two"));
    assertThat(a.state().active()).containsExactly("Par", "R1", "b1", "R2", "b2");
  }

  @Test
  void aMicrostepOfSeveralTransitionsIsReplayedByItsName() {
    Statechart chart = Statechart.of(REGIONS);
    Activation<Configuration> model = start(chart);
    Step<Configuration> step = model.apply("t1 t2", null);
    assertThat(step.result()).isEqualTo(List.of("one", "two"));
    assertThat(model.state().active()).containsExactly("Par", "R1", "b1", "R2", "b2");
    assertThatThrownBy(() -> model.apply("t1 nowhere", null))
        .isInstanceOf(org.armgals.representation.NoSuchBehaviorException.class)
        .hasMessageContaining("t1 nowhere");
    assertThatThrownBy(() -> model.apply("t1 t2", null))
        .isInstanceOf(org.armgals.representation.BehaviorNotApplicableException.class);
  }

  @Test
  void anInGuardSeesTheOtherRegion() {
    Activation<Configuration> a = start(REGIONS);
    assertThat(a.dispatch("f", null)).isEmpty();
    a.reset(new Configuration(java.util.Set.of("Par", "R1", "b1", "R2", "a2"), Map.of()));
    assertThat(behaviors(a.dispatch("f", null))).containsExactly("t3");
  }

  @Test
  void aTransitionOfAChildWinsOverOneOfItsParentOnTheSameEvent() {
    Activation<Configuration> a =
        start(
            ScDefinition.of(
                    "priority",
                    ScNode.state("P", ScNode.state("C1"), ScNode.state("C2")),
                    ScNode.state("Q"))
                .withTransitions(
                    ScTransition.on("parent", "P", "e", "Q"),
                    ScTransition.on("child", "C1", "e", "C2")));
    assertThat(behaviors(a.dispatch("e", null))).containsExactly("child");
    assertThat(behaviors(a.dispatch("e", null))).containsExactly("parent");
  }

  @Test
  void enteringAFinalChildRaisesDoneAndTheDoneTransitionIsTakenInTheSameStep() {
    Activation<Configuration> a =
        start(
            ScDefinition.of(
                    "job",
                    ScNode.state("Job", ScNode.state("Work"), ScNode.finalState("Finished")),
                    ScNode.state("Report"))
                .withTransitions(
                    ScTransition.on("finish", "Work", "finish", "Finished"),
                    ScTransition.on("report", "Job", "done.state.Job", "Report")));
    assertThat(behaviors(a.dispatch("finish", null))).containsExactly("finish", "report");
    assertThat(a.state().active()).containsExactly("Report");
  }

  @Test
  void aParallelStateIsDoneWhenEveryRegionIsInAFinalState() {
    Activation<Configuration> a =
        start(
            ScDefinition.of(
                    "both",
                    ScNode.parallel(
                        "Par",
                        ScNode.state("R1", ScNode.state("a1"), ScNode.finalState("f1")),
                        ScNode.state("R2", ScNode.state("a2"), ScNode.finalState("f2"))),
                    ScNode.state("End"))
                .withTransitions(
                    ScTransition.on("x", "a1", "x", "f1"),
                    ScTransition.on("y", "a2", "y", "f2"),
                    ScTransition.on("end", "Par", "done.state.Par", "End")));
    assertThat(behaviors(a.dispatch("x", null))).containsExactly("x");
    assertThat(behaviors(a.dispatch("y", null))).containsExactly("y", "end");
    assertThat(a.state().active()).containsExactly("End");
  }

  @Test
  void aRunToCompletionStepTakesEventlessTransitionsBeforeRaisedEventsInOrder() {
    Activation<Configuration> a =
        start(
            ScDefinition.of(
                    "rtc",
                    ScNode.state("A"),
                    ScNode.state("B"),
                    ScNode.state("C"),
                    ScNode.state("D"),
                    ScNode.state("E"))
                .withTransitions(
                    ScTransition.on("go", "A", "go", "B").doing(raise("r1"), raise("r2")),
                    ScTransition.eventless("settle", "B", "C"),
                    ScTransition.on("first", "C", "r1", "D"),
                    ScTransition.on("second", "D", "r2", "E"),
                    ScTransition.on("wrong", "B", "r1", "A")));
    assertThat(behaviors(a.dispatch("go", null)))
        .containsExactly("go", "settle", "first", "second");
    assertThat(a.state().active()).containsExactly("E");
  }

  @Test
  void aTopLevelFinalStateFinishesTheChart() {
    Statechart chart =
        Statechart.of(
            ScDefinition.of("end", ScNode.state("A"), ScNode.finalState("Z"))
                .withTransitions(
                    ScTransition.on("quit", "A", "quit", "Z"),
                    ScTransition.on("any", "A", "*", "A")));
    Activation<Configuration> a = start(chart);
    assertThat(chart.isFinished(a.state())).isFalse();
    a.dispatch("quit", null);
    assertThat(chart.isFinished(a.state())).isTrue();
    assertThat(a.dispatch("quit", null)).isEmpty();
    assertThat(a.dispatch("whatever", null)).isEmpty();
  }

  @Test
  void eventDescriptorsMatchByTokenPrefixAndStarMatchesAll() {
    Activation<Configuration> a =
        start(
            ScDefinition.of("events", ScNode.state("A"), ScNode.state("B"))
                .withTransitions(
                    ScTransition.on("ab", "A", "error.io", "B"),
                    ScTransition.on("ba", "B", "*", "A")));
    assertThat(a.dispatch("error", null)).isEmpty();
    assertThat(a.dispatch("error.iox", null)).isEmpty();
    assertThat(behaviors(a.dispatch("error.io.disk", null))).containsExactly("ab");
    assertThat(behaviors(a.dispatch("anything", null))).containsExactly("ba");
  }

  @Test
  void aNamedGuardDecidesWithTheTriggersInput() {
    Statechart chart =
        Statechart.of(
            ScDefinition.of("guarded", ScNode.state("A"), ScNode.state("B"))
                .withTransitions(ScTransition.on("t", "A", "e", "B").when("big")),
            Map.of("big", (c, in) -> in instanceof Integer n && n > 10));
    Activation<Configuration> a = start(chart);
    assertThat(a.dispatch("e", 3)).isEmpty();
    assertThat(behaviors(a.dispatch("e", 30))).containsExactly("t");
  }

  @Test
  void aConfigurationForcedWhereAnEventlessTransitionIsEnabledComesToRestAtTheNextDispatch() {
    Statechart chart =
        Statechart.of(
            ScDefinition.of("rest", ScNode.state("A"), ScNode.state("B"), ScNode.state("C"))
                .withTransitions(
                    ScTransition.on("ab", "A", "go", "B"), ScTransition.eventless("bc", "B", "C")));
    Activation<Configuration> a = start(chart);
    a.reset(new Configuration(java.util.Set.of("B"), Map.of()));
    assertThat(behaviors(a.dispatch("unknown", null))).containsExactly("bc");
    assertThat(a.state().active()).containsExactly("C");
  }

  @Test
  void aLoopOfEventlessTransitionsIsReportedAndLeavesTheStateAlone() {
    Activation<Configuration> a =
        start(
            ScDefinition.of("loop", ScNode.state("A"), ScNode.state("B"), ScNode.state("C"))
                .withTransitions(
                    ScTransition.on("go", "A", "go", "B"),
                    ScTransition.eventless("bc", "B", "C"),
                    ScTransition.eventless("cb", "C", "B")));
    Configuration before = a.state();
    assertThatThrownBy(() -> a.dispatch("go", null))
        .isInstanceOf(RepresentationException.class)
        .hasMessageContaining("more than " + ScActivation.MAX_MICROSTEPS);
    assertThat(a.state()).isEqualTo(before);
  }

  @Test
  void aCoarseObservationAnswersEveryConfigurationInsideTheCompositeState() {
    Statechart chart = ScContractTest.CHART;
    Activation<Configuration> a = start(chart);
    a.dispatch("power", null);
    a.dispatch("go", null);
    a.dispatch("faster", null);
    Configuration fine = a.state();
    assertThat(fine.active())
        .containsExactly("On", "Moving", "Drive", "Fast", "Sensor", "Scanning");

    assertThat(chart.observe(fine, 1)).isEqualTo(Map.of("active", List.of("On")));
    assertThat(chart.mapToState(chart.observe(fine, 1), fine)).hasSize(5).contains(fine);
    assertThat(chart.mapToState(chart.observe(fine, 2), fine)).hasSize(4).contains(fine);
    assertThat(chart.mapToState(Map.of("active", List.of("Fast")), fine))
        .hasSize(2)
        .allSatisfy(c -> assertThat(c.active()).contains("On", "Moving", "Fast"));
    assertThat(chart.mapToState(Map.of("active", List.of("Idle", "Fast")), fine)).isEmpty();
    assertThat(chart.mapToState(Map.of(), null)).hasSize(1 + 5 + 1);
  }

  @Test
  void aStepChangesTheCoarseGrainOnlyWhenItLeavesTheCompositeState() {
    Statechart chart = ScContractTest.CHART;
    Activation<Configuration> a = start(chart);
    Step<Configuration> power = a.dispatch("power", null).get(0);
    Step<Configuration> go = a.dispatch("go", null).get(0);
    assertThat(chart.changedAt(power, 1)).isTrue();
    assertThat(chart.changedAt(go, 1)).isFalse();
    assertThat(chart.changedAt(go, 2)).isTrue();
  }

  @Test
  void aCoarseObservationKeepsTheHistoryOfTheCurrentState() {
    Statechart chart = Statechart.of(HISTORY);
    Activation<Configuration> a = start(chart);
    a.dispatch("enter", null);
    a.dispatch("next", null);
    a.dispatch("leave", null);
    Configuration current = a.state();
    assertThat(chart.mapToState(Map.of("active", List.of("Out")), current))
        .containsExactly(current);
    assertThat(
            chart.mapToState(
                Map.of("active", List.of("Out"), "history.HD", List.of("X1")), current))
        .singleElement()
        .satisfies(c -> assertThat(c.history()).containsEntry("HD", List.of("X1")));
  }

  @Test
  void aChartWithTooManyConfigurationsToEnumerateRefusesACoarseObservation() {
    ScNode[] regions = new ScNode[6];
    for (int r = 0; r < regions.length; r++) {
      ScNode[] leaves = new ScNode[10];
      for (int l = 0; l < leaves.length; l++) {
        leaves[l] = ScNode.state("s" + r + "_" + l);
      }
      regions[r] = ScNode.state("r" + r, leaves);
    }
    Statechart chart = Statechart.of(ScDefinition.of("wide", ScNode.parallel("P", regions)));
    assertThat(chart.contains(chart.initialState())).isTrue();
    assertThatThrownBy(() -> chart.mapToState(Map.of("active", List.of("P")), null))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("100000");
  }

  @Test
  void badObservationsAreRefusedWithTheCulprit() {
    Statechart chart = Statechart.of(HISTORY);
    assertThatThrownBy(() -> chart.mapToState(Map.of("active", List.of("Nowhere")), null))
        .hasMessageContaining("Nowhere");
    assertThatThrownBy(() -> chart.mapToState(Map.of("active", "P"), null))
        .hasMessageContaining("expected a list");
    assertThatThrownBy(() -> chart.mapToState(Map.of("history.HD", List.of("Out")), null))
        .hasMessageContaining("history.HD");
    assertThatThrownBy(() -> chart.mapToState(Map.of("active", List.of("HS")), null))
        .hasMessageContaining("HS");
    assertThatThrownBy(() -> chart.observe(chart.initialState(), 0)).hasMessageContaining("0");
  }

  @Test
  void onlyTransitionsBoundToThisChartMayJoinItsBehaviors() {
    Statechart chart = ScContractTest.CHART;
    Statechart twin = Statechart.of(ScContractTest.ROBOT, Map.of("near", (c, in) -> false));
    assertThatThrownBy(
            () ->
                chart.transitions().with(twin.bind(ScTransition.on("elsewhere", "Off", "k", "On"))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'elsewhere'")
        .hasMessageContaining("bind");
    Activation<Configuration> a = start(chart);
    assertThatThrownBy(() -> a.harmonize(twin.transitions()))
        .isInstanceOf(IllegalArgumentException.class);
    assertThat(a.behaviors()).isSameAs(chart.transitions());
  }

  @Test
  void aDefinitionThatDoesNotHoldTogetherIsRefusedWithTheCulprit() {
    assertThatThrownBy(
            () -> Statechart.of(ScDefinition.of("dup", ScNode.state("A", ScNode.state("A")))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'A'");
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("target", ScNode.state("A"))
                        .withTransitions(ScTransition.on("t", "A", "e", "Nowhere"))))
        .hasMessageContaining("Nowhere");
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("guard", ScNode.state("A"))
                        .withTransitions(ScTransition.on("t", "A", "e", "A").when("missing"))))
        .hasMessageContaining("missing");
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("final", ScNode.finalState("F"), ScNode.state("A"))
                        .withTransitions(ScTransition.on("t", "F", "e", "A"))))
        .hasMessageContaining("'F'");
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of(
                        "initial",
                        ScNode.state("A", ScNode.state("A1")).withInitial("B"),
                        ScNode.state("B"))))
        .hasMessageContaining("'B'");
    assertThatThrownBy(() -> ScNode.state("has space")).hasMessageContaining("has space");
    assertThatThrownBy(
            () ->
                Statechart.of(
                    ScDefinition.of("twice", ScNode.state("A"))
                        .withTransitions(
                            ScTransition.on("t", "A", "e", "A"),
                            ScTransition.on("t", "A", "f", "A"))))
        .hasMessageContaining("'t'");
  }
}
