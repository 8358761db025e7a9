package org.armgals.representation;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.representation.dfa.DfaSpace;
import org.armgals.representation.dfa.DfaState;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PSpace;
import org.armgals.representation.p.PState;
import org.armgals.representation.sc.Configuration;
import org.armgals.representation.sc.Guard;
import org.armgals.representation.sc.ScAction;
import org.armgals.representation.sc.ScDefinition;
import org.armgals.representation.sc.ScNode;
import org.armgals.representation.sc.ScTransition;
import org.armgals.representation.sc.Scxml;
import org.armgals.representation.sc.Statechart;
import org.junit.jupiter.api.Test;

/** The worked examples of docs/representations.md, which shows the tagged regions. */
class RepresentationExamplesTest {

  // tag::p-record[]
  record Rover(int battery, boolean moving) {}

  // end::p-record[]

  @Test
  void procedural() {
    // tag::p[]
    PSpace space = PSpace.ofRecord(new Rover(100, false));
    PMethod drive =
        PMethod.returning(
                "drive",
                (s, in) -> {
                  int left = (Integer) s.get("battery") - 10;
                  return new PMethod.Outcome(s.with("battery", left).with("moving", true), left);
                })
            .when((s, in) -> (Integer) s.get("battery") >= 10);
    PMethod stop = PMethod.of("stop", (s, in) -> s.with("moving", false));

    Activation<PState> rover = space.activate(space.initialState(), space.methods(drive, stop));
    Step<PState> step = rover.apply("drive", null); // result 90
    Rover now = rover.state().as(Rover.class); // Rover[battery=90, moving=true]

    // A differential state event carries only what changed; the rest comes from `current`.
    Set<PState> seen = space.mapToState(Map.of("battery", 42), rover.state());
    // {PState{battery=42, moving=true}}
    // end::p[]
    assertThat(step.result()).isEqualTo(90);
    assertThat(now).isEqualTo(new Rover(90, true));
    assertThat(seen).containsExactly(PState.of(new Rover(42, true)));
  }

  @Test
  void dfa() {
    // tag::dfa[]
    DfaSpace door =
        DfaSpace.builder()
            .state("closed", Map.of("passable", false))
            .state("open", Map.of("passable", true))
            .state("locked", Map.of("passable", false))
            .transition("opening", "closed", "open", "open")
            .transition("closing", "open", "close", "closed")
            .transition("locking", "closed", "lock", "locked")
            .transition("unlocking", "locked", "unlock", "closed")
            .build();
    Activation<DfaState> a = door.activate(door.initialState(), door.transitions());
    List<Step<DfaState>> steps = a.dispatch("open", null); // one step, behavior "opening"

    // A sensor that only sees whether the door can be passed cannot tell closed from locked.
    Set<DfaState> candidates = door.mapToState(Map.of("passable", false), null);
    // {closed, locked}
    // end::dfa[]
    assertThat(steps).extracting(Step::behavior).containsExactly("opening");
    assertThat(candidates).containsExactly(door.state("closed"), door.state("locked"));
  }

  @Test
  void statechart() throws IOException {
    String document;
    try (InputStream in =
        getClass().getResourceAsStream("/org/armgals/representation/sc/robot.scxml")) {
      document = new String(in.readAllBytes(), StandardCharsets.UTF_8);
    }
    List<String> ran = new ArrayList<>();
    // tag::sc[]
    Map<String, Guard> guards = Map.of("notCharging", (c, in) -> !c.isActive("Charging"));
    Statechart chart = Statechart.of(Scxml.read(document), guards);
    Activation<Configuration> robot = chart.activate(chart.initialState(), chart.transitions());
    ran.addAll(chart.initialActions()); // [startMotors]

    for (Step<Configuration> step : robot.dispatch("bump", null)) {
      // The chart names the actions; the entity runs them (a model replaying the step does not).
      if (step.result() instanceof List<?> actions) {
        actions.forEach(action -> ran.add((String) action)); // beep
      }
    }
    // Two steps: Forward -> Turning raises "obstacle", which takes Wide -> Zoom in the same
    // run-to-completion step.

    // Coarse grain: only the top-level state is notified; the meta gets every configuration
    // consistent with it.
    Map<String, Object> coarse = chart.observe(robot.state(), 1); // {active=[Active]}
    Set<Configuration> candidates = chart.mapToState(coarse, robot.state()); // 4 configurations
    // end::sc[]
    assertThat(ran).containsExactly("startMotors", "beep");
    assertThat(robot.state().active()).contains("Turning", "Zoom");
    assertThat(coarse).isEqualTo(Map.of("active", List.of("Active")));
    assertThat(candidates).hasSize(4).contains(robot.state());
  }

  @Test
  void aStatechartDefinedInJava() {
    // tag::sc-java[]
    ScDefinition lamp =
        ScDefinition.of(
                "lamp", ScNode.state("Off"), ScNode.state("On").onEntry(ScAction.run("lightUp")))
            .withTransitions(
                ScTransition.on("switchOn", "Off", "press", "On"),
                ScTransition.on("switchOff", "On", "press", "Off"));
    String scxml = Scxml.write(lamp); // and Scxml.read(scxml) equals lamp
    // end::sc-java[]
    assertThat(Scxml.read(scxml)).isEqualTo(lamp);
  }
}
