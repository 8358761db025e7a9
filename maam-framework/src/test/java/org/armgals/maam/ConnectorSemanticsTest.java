package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import org.junit.jupiter.api.Test;

/** Inhibitors, suppressors and derivators in running robots, with their hold times. */
class ConnectorSemanticsTest {

  private static final Duration TWO_PERIODS = Duration.ofMillis(20);

  private final Sensing wander = new Sensing("wander", TestRobot.WANDER, 0);
  private final Sensing avoid = new Sensing("avoid", TestRobot.OBSTACLE, 100);
  private final Drive motor = new Drive("motor", TestRobot.MOTOR);

  private TestRobot wanderer() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(
        Schema.builder("wander")
            .add(wander)
            .add(motor)
            .wire(wander, Sensing.OUT, motor, Drive.IN)
            .build());
    robot.addBehaviorModule(avoid);
    return robot;
  }

  @Test
  void inhibitorBlocksInputWhileSourceIsActiveAndForHoldTime() {
    TestRobot robot = wanderer();
    robot.addConnector(
        new Inhibitor(PortRef.of(avoid, Sensing.OUT), PortRef.of(motor, Drive.IN), TWO_PERIODS));
    assertThat(robot.step(5, 0)).isEqualTo(5);
    assertThat(robot.step(5, 1)).as("source active").isEqualTo(-1);
    assertThat(robot.step(5, 0)).as("one period after").isEqualTo(-1);
    assertThat(robot.step(5, 0)).as("two periods after: the hold's end, included").isEqualTo(-1);
    assertThat(robot.step(5, 0)).as("hold over").isEqualTo(5);
  }

  @Test
  void inhibitorWithZeroHoldBlocksOnlyCyclesWhereItsSourceIsActive() {
    TestRobot robot = wanderer();
    robot.addConnector(
        new Inhibitor(PortRef.of(avoid, Sensing.OUT), PortRef.of(motor, Drive.IN), Duration.ZERO));
    assertThat(robot.step(5, 1)).isEqualTo(-1);
    assertThat(robot.step(5, 0)).isEqualTo(5);
    assertThat(robot.step(5, 1)).isEqualTo(-1);
  }

  @Test
  void inhibitorHoldIsRenewedByEachActiveCycle() {
    TestRobot robot = wanderer();
    robot.addConnector(
        new Inhibitor(
            PortRef.of(avoid, Sensing.OUT), PortRef.of(motor, Drive.IN), Duration.ofMillis(10)));
    assertThat(robot.step(5, 1)).isEqualTo(-1);
    assertThat(robot.step(5, 0)).isEqualTo(-1);
    assertThat(robot.step(5, 1)).isEqualTo(-1);
    assertThat(robot.step(5, 0)).isEqualTo(-1);
    assertThat(robot.step(5, 0)).isEqualTo(5);
  }

  @Test
  void suppressorReplacesOutputWithTheLatchedSignalForHoldTime() {
    TestRobot robot = wanderer();
    robot.addConnector(
        new Suppressor(
            PortRef.of(avoid, Sensing.OUT), PortRef.of(wander, Sensing.OUT), TWO_PERIODS));
    assertThat(robot.step(5, 0)).isEqualTo(5);
    assertThat(robot.step(5, 7)).as("replaced").isEqualTo(107);
    assertThat(robot.step(5, 0)).as("latched, one period after").isEqualTo(107);
    assertThat(robot.step(0, 0)).as("latched even when the target is silent").isEqualTo(107);
    assertThat(robot.step(5, 0)).as("hold over").isEqualTo(5);
  }

  @Test
  void suppressedSignalIsWhatTheRobotObserves() {
    TestRobot robot = wanderer();
    robot.addConnector(
        new Suppressor(
            PortRef.of(avoid, Sensing.OUT), PortRef.of(wander, Sensing.OUT), Duration.ZERO));
    robot.step(5, 1);
    assertThat(robot.emissions())
        .contains(new Emission(PortRef.of(wander, Sensing.OUT), new Num(101)));
  }

  @Test
  void derivatorBranchesASignalToAModuleOfAnotherSchema() {
    TestRobot robot = TestRobot.create();
    Drive other = new Drive("other", TestRobot.OTHER_MOTOR);
    robot.addBehaviorModule(other);
    robot.addSchema(
        Schema.builder("wander")
            .add(wander)
            .add(motor)
            .wire(wander, Sensing.OUT, motor, Drive.IN)
            .build());
    robot.addConnector(new Derivator(PortRef.of(wander, Sensing.OUT), PortRef.of(other, Drive.IN)));
    assertThat(robot.schedule().names()).containsExactly("wander", "other", "motor");
    assertThat(robot.step(3, 0)).isEqualTo(3);
    assertThat(robot.fake.lastCommand(TestRobot.OTHER_MOTOR)).contains(3);
  }

  @Test
  void connectorsMakeTheirSourceRunFirstWhateverTheSchemaOrder() {
    TestRobot robot = TestRobot.create();
    robot.addSchema(
        Schema.builder("wander")
            .add(wander)
            .add(motor)
            .wire(wander, Sensing.OUT, motor, Drive.IN)
            .build());
    assertThat(robot.schedule().names()).containsExactly("wander", "motor");
    robot.addBehaviorModule(avoid);
    assertThat(robot.schedule().names()).containsExactly("wander", "motor", "avoid");
    robot.addConnector(
        new Inhibitor(PortRef.of(avoid, Sensing.OUT), PortRef.of(motor, Drive.IN), Duration.ZERO));
    assertThat(robot.schedule().names()).containsExactly("wander", "avoid", "motor");
  }

  @Test
  void reschedulingDoesNotCutAHoldShort() {
    TestRobot robot = wanderer();
    Inhibitor inhibitor =
        new Inhibitor(PortRef.of(avoid, Sensing.OUT), PortRef.of(motor, Drive.IN), TWO_PERIODS);
    robot.addConnector(inhibitor);
    assertThat(robot.step(5, 1)).isEqualTo(-1);
    robot.addBehaviorModule(new Drive("spare", TestRobot.OTHER_MOTOR));
    assertThat(robot.step(5, 0)).as("still held after rescheduling").isEqualTo(-1);
  }

  @Test
  void aFailingModuleLosesItsOutputsForTheCycleAndTheOthersGoOn() {
    TestRobot robot = TestRobot.create();
    Perceptor broken =
        new Perceptor() {
          @Override
          public String name() {
            return "broken";
          }

          @Override
          public java.util.List<Port<?>> outputs() {
            return java.util.List.of(Sensing.OUT);
          }

          @Override
          public void perceive(org.armgals.maam.spi.Body body, Outputs out) {
            out.emit(Sensing.OUT, new Num(1));
            throw new IllegalStateException("sensor glitch");
          }
        };
    robot.addSchema(
        Schema.builder("s")
            .add(broken)
            .add(motor)
            .wire(broken, Sensing.OUT, motor, Drive.IN)
            .build());
    assertThat(robot.step(0, 0)).isEqualTo(-1);
    assertThat(robot.errors()).isEqualTo(1);
    assertThat(robot.errors).containsExactly("broken: sensor glitch");
  }
}
