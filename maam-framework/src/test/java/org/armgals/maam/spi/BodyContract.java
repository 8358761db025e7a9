package org.armgals.maam.spi;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/**
 * What every {@link Body} of an atom must do; a subclass per implementation supplies the body. The
 * simulator's bodies are held to the same rules.
 */
abstract class BodyContract {

  /** A fresh atom body named {@code id}. */
  abstract Body atom(String id);

  @Test
  void atomBodyHasEveryAtomSensorAndActuator() {
    Body body = atom("a1");
    assertThat(body.id()).isEqualTo("a1");
    assertThat(body.sensors()).containsAll(Atom.sensors());
    assertThat(body.actuators()).containsAll(Atom.actuators());
  }

  @Test
  void everyAtomSensorReadsAValueOfItsType() {
    Body body = atom("a1");
    for (SensorKey<?> sensor : Atom.sensors()) {
      assertThat(body.read(sensor)).as(sensor.name()).isInstanceOf(sensor.type());
    }
  }

  @Test
  void unknownSensorIsRefusedWithItsName() {
    Body body = atom("a1");
    assertThatThrownBy(() -> body.read(SensorKey.of("sonar", Double.class)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("sonar");
  }

  @Test
  void unknownActuatorIsRefusedWithItsName() {
    Body body = atom("a1");
    assertThatThrownBy(() -> body.command(ActuatorKey.of("wheel", Double.class), 1.0))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("wheel");
  }

  @Test
  @SuppressWarnings({"unchecked", "rawtypes"})
  void commandOfTheWrongTypeIsRefusedWithBothTypes() {
    Body body = atom("a1");
    ActuatorKey raw = Atom.torque(Leg.PX);
    assertThatThrownBy(() -> body.command(raw, "strong"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("java.lang.Double")
        .hasMessageContaining("java.lang.String");
  }

  @Test
  void sensorAndActuatorSetsAreUnmodifiable() {
    Body body = atom("a1");
    assertThatThrownBy(() -> body.sensors().clear())
        .isInstanceOf(UnsupportedOperationException.class);
    assertThatThrownBy(() -> body.actuators().clear())
        .isInstanceOf(UnsupportedOperationException.class);
  }
}
