package org.armgals.maam;

import java.util.List;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Body;

/** An actuator for the tests: commands the value on {@link #IN}, or -1 when there is none. */
record Drive(String name, ActuatorKey<Integer> actuator) implements Actuator {

  static final Port<Num> IN = Port.of("in", Num.class);

  @Override
  public List<Port<?>> inputs() {
    return List.of(IN);
  }

  @Override
  public void act(Inputs in, Body body) {
    Num value = in.get(IN);
    body.command(actuator, value == null ? -1 : value.value());
  }
}
