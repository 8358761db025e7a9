package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Bad wiring is refused when built; a module using a port it did not declare fails its step. */
class PortMisuseTest {

  private static final Port<Num> UNDECLARED = Port.of("undeclared", Num.class);

  @Test
  void emittingOnAnUndeclaredPortFailsTheStepNamingPortAndModule() {
    TestRobot robot = TestRobot.create();
    robot.addBehaviorModule(
        new Reactor() {
          @Override
          public String name() {
            return "sloppy";
          }

          @Override
          public List<Port<?>> inputs() {
            return List.of();
          }

          @Override
          public List<Port<?>> outputs() {
            return List.of(Node.OUT);
          }

          @Override
          public void react(Inputs in, Outputs out) {
            out.emit(UNDECLARED, new Num(1));
          }
        });
    robot.cycle();
    assertThat(robot.errors)
        .singleElement()
        .asString()
        .contains("sloppy")
        .contains("output undeclared:Num")
        .contains("expected one of [out:Num]");
  }

  @Test
  void readingAnUndeclaredInputFailsTheStepNamingPortAndModule() {
    TestRobot robot = TestRobot.create();
    robot.addBehaviorModule(
        new Actuator() {
          @Override
          public String name() {
            return "reader";
          }

          @Override
          public List<Port<?>> inputs() {
            return List.of(Drive.IN);
          }

          @Override
          public void act(Inputs in, org.armgals.maam.spi.Body body) {
            in.get(UNDECLARED);
          }
        });
    robot.cycle();
    assertThat(robot.errors).singleElement().asString().contains("input undeclared:Num");
  }

  @Test
  void aWireBetweenIncompatibleTypesIsRefusedNamingBothTypes() {
    Port<Signal> anything = Port.of("anything", Signal.class);
    Reactor wide =
        new Reactor() {
          @Override
          public String name() {
            return "wide";
          }

          @Override
          public List<Port<?>> inputs() {
            return List.of();
          }

          @Override
          public List<Port<?>> outputs() {
            return List.of(anything);
          }

          @Override
          public void react(Inputs in, Outputs out) {}
        };
    Drive narrow = new Drive("narrow", TestRobot.MOTOR);
    @SuppressWarnings({"unchecked", "rawtypes"})
    Port<Signal> narrowIn = (Port) Drive.IN;
    Schema.Builder builder =
        Schema.builder("s").add(wide).add(narrow).wire(wide, anything, narrow, narrowIn);
    assertThatThrownBy(builder::build)
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("narrow.in takes org.armgals.maam.Num")
        .hasMessageContaining("wide.anything carries org.armgals.maam.Signal");
  }

  @Test
  void twoWiresIntoOneInputAreRefused() {
    Sensing a = new Sensing("a", TestRobot.WANDER, 0);
    Sensing b = new Sensing("b", TestRobot.OBSTACLE, 0);
    Drive motor = new Drive("motor", TestRobot.MOTOR);
    Schema.Builder builder =
        Schema.builder("s")
            .add(a)
            .add(b)
            .add(motor)
            .wire(a, Sensing.OUT, motor, Drive.IN)
            .wire(b, Sensing.OUT, motor, Drive.IN);
    assertThatThrownBy(builder::build).hasMessageContaining("motor.in fed twice");
  }

  @Test
  void aDerivatorIntoAWiredInputIsRefusedByTheRobot() {
    TestRobot robot = TestRobot.create();
    Sensing a = new Sensing("a", TestRobot.WANDER, 0);
    Drive motor = new Drive("motor", TestRobot.MOTOR);
    robot.addSchema(
        Schema.builder("s").add(a).add(motor).wire(a, Sensing.OUT, motor, Drive.IN).build());
    Sensing b = new Sensing("b", TestRobot.OBSTACLE, 0);
    robot.addBehaviorModule(b);
    assertThatThrownBy(
            () ->
                robot.addConnector(
                    new Derivator(PortRef.of(b, Sensing.OUT), PortRef.of(motor, Drive.IN))))
        .hasMessageContaining("motor.in is already fed by a.out -> motor.in");
  }
}
