package org.armgals.representation.sc;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.RepresentationContract;
import org.armgals.representation.StateSpace;

class ScContractTest extends RepresentationContract<Configuration> {
  /** A robot: off, or on and idle or moving (driving and scanning at once), or done. */
  static final ScDefinition ROBOT =
      ScDefinition.of(
              "robot",
              ScNode.state("Off"),
              ScNode.state(
                      "On",
                      ScNode.history("H", true),
                      ScNode.state("Idle"),
                      ScNode.parallel(
                          "Moving",
                          ScNode.state("Drive", ScNode.state("Slow"), ScNode.state("Fast")),
                          ScNode.state("Sensor", ScNode.state("Scanning"), ScNode.state("Alert"))))
                  .onEntry(ScAction.run("powerUp"))
                  .onExit(ScAction.run("powerDown")),
              ScNode.finalState("Done"))
          .withTransitions(
              ScTransition.on("power", "Off", "power", "On"),
              ScTransition.on("off", "On", "power.off", "Off"),
              ScTransition.on("go", "Idle", "go", "Moving"),
              ScTransition.on("faster", "Slow", "faster", "Fast").doing(ScAction.run("accelerate")),
              ScTransition.on("alarm", "Scanning", "obstacle", "Alert").when("near"),
              ScTransition.on("stop", "Moving", "stop", "Idle"),
              ScTransition.on("resume", "Off", "resume", "H"),
              ScTransition.on("quit", "Off", "quit", "Done"));

  static final Statechart CHART =
      Statechart.of(ROBOT, Map.of("near", (c, in) -> in instanceof Integer d && d < 10));

  @Override
  protected StateSpace<Configuration> space() {
    return CHART;
  }

  @Override
  protected Behaviors<Configuration> behaviors() {
    return CHART.transitions();
  }

  @Override
  protected Trigger applicable() {
    return new Trigger("power", null);
  }

  @Override
  protected String inapplicable() {
    return "go";
  }

  @Override
  protected List<Trigger> triggers() {
    return List.of(
        new Trigger("power", null),
        new Trigger("go", null),
        new Trigger("faster", null),
        new Trigger("obstacle", 50),
        new Trigger("obstacle", 5),
        new Trigger("power.off", null),
        new Trigger("resume", null),
        new Trigger("stop", null),
        new Trigger("power.off", null),
        new Trigger("quit", null));
  }

  @Override
  protected String idleTrigger() {
    return "go";
  }

  @Override
  protected Behavior<Configuration> extra() {
    return EXTRA;
  }

  private static final Behavior<Configuration> EXTRA =
      CHART.bind(ScTransition.on("extra", "Off", "kick", "On"));

  @Override
  protected Configuration outside() {
    return new Configuration(Set.of("Off", "Idle"), Map.of("H", List.of()));
  }

  @Override
  protected Map<String, Object> partialObservation(Configuration state) {
    return CHART.observe(state, 1);
  }
}
