package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.kernel.AdaptationPoint;
import org.junit.jupiter.api.Test;

/** The adaptation protocol: requests, the two adaptation points, the behavioral meta's model. */
class AdaptationTest {

  private final Sensing wander = new Sensing("wander", TestRobot.WANDER, 0);
  private final Sensing avoid = new Sensing("avoid", TestRobot.OBSTACLE, 100);
  private final Drive motor = new Drive("motor", TestRobot.MOTOR);
  private final Schema wandering =
      Schema.builder("wander")
          .add(wander)
          .add(motor)
          .wire(wander, Sensing.OUT, motor, Drive.IN)
          .build();
  private final Inhibitor avoidInhibitsMotor =
      new Inhibitor(PortRef.of(avoid, Sensing.OUT), PortRef.of(motor, Drive.IN), Duration.ZERO);

  @Test
  void atTheEndOfACycleAnAdaptationIsInPlaceWhenTheCycleReturns() {
    TestRobot robot = TestRobot.create();
    robot.point(AdaptationPoint.END_OF_CYCLE);
    robot.addSchema(wandering);
    List<String> seen = new ArrayList<>();
    robot.bmeta(
        (report, requests) -> {
          seen.add(report.cycle() + ":" + report.applied().size());
          if (report.cycle() == 1) {
            requests.accept(
                new Adaptation.ChangeModule(new Sensing("wander", TestRobot.WANDER, 50)));
          }
        });
    assertThat(robot.step(5, 0)).isEqualTo(5);
    assertThat(robot.schedule().modules()).contains(new Sensing("wander", TestRobot.WANDER, 50));
    assertThat(robot.step(5, 0)).isEqualTo(55);
    assertThat(seen).containsExactly("1:0", "2:1");
  }

  @Test
  void atTheBeginningOfACycleAnAdaptationWaitsForTheNextCycleAndRunsInIt() {
    TestRobot robot = TestRobot.create();
    robot.point(AdaptationPoint.BEGIN_OF_CYCLE);
    robot.addSchema(wandering);
    List<String> seen = new ArrayList<>();
    robot.bmeta(
        (report, requests) -> {
          seen.add(report.cycle() + ":" + report.applied().size());
          if (report.cycle() == 1) {
            requests.accept(
                new Adaptation.ChangeModule(new Sensing("wander", TestRobot.WANDER, 50)));
          }
        });
    assertThat(robot.step(5, 0)).isEqualTo(5);
    assertThat(robot.schedule().modules()).as("not yet").contains(wander);
    assertThat(robot.step(5, 0)).isEqualTo(55);
    assertThat(seen).as("reported in the cycle it was applied in").containsExactly("1:0", "2:1");
  }

  @Test
  void aRequestFromAModuleIsAppliedAtTheEndOfItsOwnCycleOrTheBeginningOfTheNext() {
    for (AdaptationPoint point :
        List.of(AdaptationPoint.BEGIN_OF_CYCLE, AdaptationPoint.END_OF_CYCLE)) {
      TestRobot robot = TestRobot.create();
      robot.point(point);
      Reactor asker =
          new Reactor() {
            @Override
            public String name() {
              return "asker";
            }

            @Override
            public List<Port<?>> inputs() {
              return List.of();
            }

            @Override
            public List<Port<?>> outputs() {
              return List.of();
            }

            @Override
            public void react(Inputs in, Outputs out) {
              if (robot.cycles() == 1) {
                robot.request(new Adaptation.AddSchema(wandering));
              }
            }
          };
      robot.addBehaviorModule(asker);
      robot.fake.set(TestRobot.WANDER, 5);
      robot.cycle();
      assertThat(robot.schedule().names())
          .as(point.toString())
          .isEqualTo(
              point == AdaptationPoint.END_OF_CYCLE
                  ? List.of("asker", "wander", "motor")
                  : List.of("asker"));
      assertThat(robot.step(5, 0)).as(point.toString()).isEqualTo(5);
    }
  }

  @Test
  void setSchedulingReplacesTheWholeProgram() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering);
    robot.request(
        new Adaptation.SetScheduling(
            List.of(Schema.builder("avoid").add(avoid).build(), wandering),
            List.of(avoidInhibitsMotor)));
    robot.step(5, 0);
    assertThat(robot.schedule().names()).containsExactly("avoid", "wander", "motor");
    assertThat(robot.step(5, 1)).isEqualTo(-1);
  }

  @Test
  void aRejectedAdaptationLeavesTheProgramAsItWasAndIsReported() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering);
    robot.addBehaviorModule(avoid);
    robot.addConnector(avoidInhibitsMotor);
    BMetaRobot.Modelled<List<CycleReport.Rejected>> rejections =
        BMetaRobot.modelled(
            List.of(),
            (model, report) -> {
              List<CycleReport.Rejected> all = new ArrayList<>(model);
              all.addAll(report.rejected());
              return all;
            },
            model -> List.of());
    robot.bmeta(rejections);
    robot.point(AdaptationPoint.BEGIN_OF_CYCLE);
    Suppressor loop =
        new Suppressor(PortRef.of(motor, Drive.IN), PortRef.of(avoid, Sensing.OUT), Duration.ZERO);
    Inhibitor backwards =
        new Inhibitor(PortRef.of(wander, Sensing.OUT), PortRef.of(motor, Drive.IN), Duration.ZERO);
    robot.request(new Adaptation.AddConnector(loop));
    robot.request(new Adaptation.RemoveSchema("nothing"));
    robot.request(new Adaptation.AddConnector(backwards));
    List<String> before = robot.schedule().names();
    robot.step(5, 0);
    assertThat(robot.rejectedAdaptations()).isEqualTo(2);
    assertThat(rejections.model())
        .extracting(CycleReport.Rejected::reason)
        .satisfiesExactly(
            reason -> assertThat(reason).contains("motor.in is not an output"),
            reason -> assertThat(reason).contains("'nothing'"));
    assertThat(robot.schedule().names()).isEqualTo(before);
    assertThat(robot.metaRobot().connectors()).containsExactly(avoidInhibitsMotor, backwards);
  }

  @Test
  void aConnectorClosingACycleIsRefusedByTheRobotNamingTheCycle() {
    TestRobot robot = TestRobot.create();
    Node a = new Node("a", 1, 0, new ArrayList<>());
    Node b = new Node("b", 1, 0, new ArrayList<>());
    robot.addSchema(Schema.builder("ab").add(a).add(b).wire(a, Node.OUT, b, Node.in(0)).build());
    long version = robot.metaRobot().version();
    assertThatThrownBy(
            () ->
                robot.addConnector(
                    new Derivator(PortRef.of(b, Node.OUT), PortRef.of(a, Node.in(0)))))
        .isInstanceOf(CycleException.class)
        .hasMessageContaining("a -> b -> a");
    assertThat(robot.metaRobot().version()).isEqualTo(version);
  }

  @Test
  void removingASchemaRemovesItsConnectorsAndReschedules() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering);
    robot.addBehaviorModule(avoid);
    robot.addConnector(avoidInhibitsMotor);
    robot.removeSchema("avoid");
    assertThat(robot.metaRobot().connectors()).isEmpty();
    assertThat(robot.schedule().names()).containsExactly("wander", "motor");
    assertThat(robot.step(5, 1)).isEqualTo(5);
  }

  @Test
  void aChangeOfModuleMustKeepItsKindAndPorts() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering);
    assertThatThrownBy(() -> robot.changeModule(new Drive("wander", TestRobot.MOTOR)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("expected a perceptor")
        .hasMessageContaining("got a actuator");
    assertThatThrownBy(() -> robot.changeModule(new Drive("ghost", TestRobot.MOTOR)))
        .hasMessageContaining("'ghost'");
  }

  @Test
  void aModelledBehavioralMetaRemovesASchemaAfterThreeObstacles() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering);
    robot.addBehaviorModule(avoid);
    PortRef avoidOut = PortRef.of(avoid, Sensing.OUT);
    BMetaRobot.Modelled<Integer> obstacles =
        BMetaRobot.modelled(
            0,
            (seen, report) ->
                seen
                    + (int)
                        report.emissions().stream().filter(e -> e.port().equals(avoidOut)).count(),
            seen -> seen == 3 ? List.of(new Adaptation.RemoveSchema("wander")) : List.of());
    robot.bmeta(obstacles);
    for (int i = 0; i < 3; i++) {
      robot.step(5, 1);
    }
    assertThat(obstacles.model()).isEqualTo(3);
    assertThat(robot.schedule().names()).containsExactly("avoid");
  }

  @Test
  void aFailingBehavioralMetaIsReportedAndTheRobotGoesOn() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering);
    robot.bmeta(
        (report, requests) -> {
          throw new IllegalStateException("model broken");
        });
    assertThat(robot.step(5, 0)).isEqualTo(5);
    assertThat(robot.step(6, 0)).isEqualTo(6);
    assertThat(robot.errors).containsExactly("bmeta: model broken", "bmeta: model broken");
  }
}
