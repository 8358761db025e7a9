package org.armgals.kernel;

import java.util.List;
import java.util.Map;
import org.armgals.representation.Behaviors;
import org.armgals.representation.State;
import org.armgals.representation.StateSpace;
import org.armgals.representation.dfa.DfaSpace;
import org.armgals.representation.p.PState;
import org.armgals.representation.sc.Scxml;
import org.armgals.representation.sc.Statechart;

/** A kind of entity in one representation family, and stimuli to drive it with. */
record Family<S extends State>(
    String name,
    StateSpace<S> space,
    Behaviors<S> behaviors,
    List<Map.Entry<String, Object>> inputs) {

  @Override
  public String toString() {
    return name;
  }

  static List<Family<?>> all() {
    return List.of(procedural(), automaton(), statechart());
  }

  static Family<PState> procedural() {
    return new Family<>(
        "P",
        KernelFixture.ROBOT,
        KernelFixture.robotBehaviors(),
        List.of(
            Map.entry("work", 0.1),
            Map.entry("eco", ""),
            Map.entry("charge", 0.05),
            Map.entry("work", 0.2),
            Map.entry("normal", "")));
  }

  static Family<?> automaton() {
    DfaSpace door =
        DfaSpace.builder()
            .state("closed")
            .state("opened")
            .state("locked")
            .initial("closed")
            .transition("t1", "closed", "open", "opened")
            .transition("t2", "opened", "close", "closed")
            .transition("t3", "closed", "lock", "locked")
            .transition("t4", "locked", "unlock", "closed")
            .build();
    return new Family<>(
        "DFA",
        door,
        door.transitions(),
        List.of(
            Map.entry("open", ""),
            Map.entry("close", ""),
            Map.entry("lock", ""),
            Map.entry("open", ""),
            Map.entry("unlock", ""),
            Map.entry("open", "")));
  }

  static final String FAN =
      """
      <scxml xmlns="http://www.w3.org/2005/07/scxml" version="1.0" initial="off">
        <state id="off"><transition event="on" target="on"/></state>
        <state id="on" initial="slow">
          <state id="slow"><transition event="faster" target="fast"/></state>
          <state id="fast"><transition event="slower" target="slow"/></state>
          <transition event="off" target="off"/>
        </state>
      </scxml>
      """;

  static Family<?> statechart() {
    Statechart fan = Statechart.of(Scxml.read(FAN));
    return new Family<>(
        "SC",
        fan,
        fan.transitions(),
        List.of(
            Map.entry("on", ""),
            Map.entry("faster", ""),
            Map.entry("slower", ""),
            Map.entry("faster", ""),
            Map.entry("off", ""),
            Map.entry("on", "")));
  }
}
