package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A robot's program changed by hand, between cycles (its registration methods): each change is
 * checked whole, applied whole or refused with the reason, and the observation shows it. ({@link
 * RobotAsKernelEntityTest} has the changes its behavioral meta requests.)
 */
class ProgramTest {

  private final WanderAndAvoid p = new WanderAndAvoid();

  @Test
  void setSchedulingReplacesTheWholeProgram() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(p.wandering);
    robot.setScheduling(
        List.of(Schema.builder("avoid").add(p.avoid).build(), p.wandering),
        List.of(p.avoidInhibitsMotor));
    assertThat(robot.schedule().names()).containsExactly("avoid", "wander", "motor");
    assertThat(robot.step(5, 1)).isEqualTo(-1);
  }

  @Test
  void aRefusedChangeLeavesTheProgramAsItWasAndSaysWhy() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(p.wandering);
    robot.addBehaviorModule(p.avoid);
    robot.addConnector(p.avoidInhibitsMotor);
    Suppressor loop =
        new Suppressor(
            PortRef.of(p.motor, Drive.IN), PortRef.of(p.avoid, Sensing.OUT), Duration.ZERO);
    List<String> before = robot.schedule().names();
    long version = robot.metaRobot().version();

    assertThatThrownBy(() -> robot.addConnector(loop))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("motor.in is not an output");
    assertThatThrownBy(() -> robot.removeSchema("nothing"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'nothing'");
    assertThat(robot.schedule().names()).isEqualTo(before);
    assertThat(robot.metaRobot().version()).isEqualTo(version);
    assertThat(robot.step(5, 1)).as("the avoid schema still inhibits the motor").isEqualTo(-1);
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
    robot.addSchema(p.wandering);
    robot.addBehaviorModule(p.avoid);
    robot.addConnector(p.avoidInhibitsMotor);
    robot.removeSchema("avoid");
    assertThat(robot.metaRobot().connectors()).isEmpty();
    assertThat(robot.schedule().names()).containsExactly("wander", "motor");
    assertThat(robot.step(5, 1)).isEqualTo(5);
  }

  @Test
  void aChangeOfModuleMustKeepItsKindAndPorts() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(p.wandering);
    assertThatThrownBy(() -> robot.changeModule(new Drive("wander", TestRobot.MOTOR)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("expected a perceptor")
        .hasMessageContaining("got a actuator");
    assertThatThrownBy(() -> robot.changeModule(new Drive("ghost", TestRobot.MOTOR)))
        .hasMessageContaining("'ghost'");
  }

  @Test
  void theObservationShowsTheProgramAndCountsItsChanges() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(p.wandering);
    robot.addBehaviorModule(p.avoid);
    robot.step(5, 0);

    assertThat(robot.observation().fields())
        .containsEntry("cycle", 1L)
        .containsEntry("program", 2L)
        .containsEntry("schemas", List.of("wander", "avoid"))
        .containsEntry("errors", 0L);
    robot.removeSchema("avoid");
    assertThat(robot.observation().fields())
        .containsEntry("program", 3L)
        .containsEntry("schemas", List.of("wander"));
  }
}
