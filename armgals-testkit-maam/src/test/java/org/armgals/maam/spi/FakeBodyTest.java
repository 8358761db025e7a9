package org.armgals.maam.spi;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.armgals.testkit.maam.FakeBody;
import org.junit.jupiter.api.Test;

class FakeBodyTest extends BodyContract {

  @Override
  Body atom(String id) {
    return FakeBody.atom(id, 100.0);
  }

  @Test
  void setSensorIsReadBack() {
    FakeBody body = FakeBody.atom("a1", 50.0);
    assertThat(body.read(Atom.BATTERY)).isEqualTo(50.0);
    body.set(Atom.contact(Leg.MZ), true);
    body.set(Atom.binding(Leg.PX), new LegBinding.Bound("a2", Leg.MX));
    assertThat(body.read(Atom.contact(Leg.MZ))).isTrue();
    assertThat(body.read(Atom.binding(Leg.PX))).isEqualTo(new LegBinding.Bound("a2", Leg.MX));
  }

  @Test
  void commandsAreKeptInOrderPerActuator() {
    FakeBody body = FakeBody.atom("a1", 50.0);
    body.command(Atom.bind(Leg.PY), BindCommand.BIND);
    body.command(Atom.bind(Leg.PY), BindCommand.UNBIND);
    body.command(Atom.SEND, new NeighbourMessage(Leg.PY, "hello"));
    assertThat(body.commands(Atom.bind(Leg.PY)))
        .containsExactly(BindCommand.BIND, BindCommand.UNBIND);
    assertThat(body.lastCommand(Atom.bind(Leg.PY))).contains(BindCommand.UNBIND);
    assertThat(body.lastCommand(Atom.bind(Leg.MY))).isEmpty();
    body.clearCommands();
    assertThat(body.commands(Atom.SEND)).isEmpty();
  }

  @Test
  void endCycleIsCounted() {
    FakeBody body = FakeBody.atom("a1", 50.0);
    body.endCycle();
    body.endCycle();
    assertThat(body.cycles()).isEqualTo(2);
  }

  @Test
  void builderRefusesADuplicateName() {
    FakeBody.Builder builder =
        FakeBody.builder("b").sensor(SensorKey.of("range", Double.class), 1.0);
    assertThatThrownBy(() -> builder.sensor(SensorKey.of("range", Integer.class), 1))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("range");
  }

  @Test
  void genericBodyHasOnlyWhatWasDeclared() {
    SensorKey<Double> range = SensorKey.of("range", Double.class);
    ActuatorKey<Double> speed = ActuatorKey.of("wheel.speed", Double.class);
    FakeBody body = FakeBody.builder("rover").sensor(range, 2.5).actuator(speed).build();
    body.command(speed, 0.3);
    assertThat(body.sensors()).containsExactly(range);
    assertThat(body.actuators()).containsExactly(speed);
    assertThat(body.commands(speed)).isEqualTo(List.of(0.3));
  }

  @Test
  void badKeyNamesAndRangesAreRefusedWithTheValue() {
    assertThatThrownBy(() -> SensorKey.of("Bad name", Double.class))
        .hasMessageContaining("Bad name");
    assertThatThrownBy(() -> new LegAngles(-0.1, 0)).hasMessageContaining("-0.1");
    assertThatThrownBy(() -> new Tilt(0, 2.0)).hasMessageContaining("2.0");
    assertThatThrownBy(() -> FakeBody.atom("a", -1)).hasMessageContaining("-1");
  }

  @Test
  void oppositeLegsPairUp() {
    for (Leg leg : Leg.values()) {
      assertThat(leg.opposite().opposite()).isEqualTo(leg);
      assertThat(leg.x() + leg.opposite().x()).isZero();
      assertThat(leg.y() + leg.opposite().y()).isZero();
      assertThat(leg.z() + leg.opposite().z()).isZero();
    }
    assertThat(Atom.angles(Leg.PX).name()).isEqualTo("leg.px.angles");
  }
}
