package org.armgals.bench.gals;

import java.util.List;
import org.armgals.maam.Actuator;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.SensorKey;

/** Small modules doing a little arithmetic, as a reflex would. */
final class BenchModules {

  static final Port<Value> IN = Port.of("in", Value.class);
  static final Port<Value> SIDE = Port.of("side", Value.class);
  static final Port<Value> OUT = Port.of("out", Value.class);
  static final SensorKey<Double> SENSOR = SensorKey.of("range", Double.class);
  static final ActuatorKey<Double> MOTOR = ActuatorKey.of("motor", Double.class);

  private BenchModules() {}

  /** Reads the range sensor. */
  record Sense(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(OUT);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      double range = body.read(SENSOR);
      if (range < 10) {
        out.emit(OUT, new Value(range));
      }
    }
  }

  /** A gain and an offset, with a second optional input. */
  record Gain(String name, double gain) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(IN, SIDE);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(OUT);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Value value = in.get(IN);
      Value side = in.get(SIDE);
      if (value != null) {
        double v = value.value() * gain + (side == null ? 0 : side.value() * 0.5);
        out.emit(OUT, new Value(Math.min(1, Math.max(-1, v))));
      }
    }
  }

  /** Commands the motor. */
  record Drive(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(IN);
    }

    @Override
    public void act(Inputs in, Body body) {
      Value value = in.get(IN);
      body.command(MOTOR, value == null ? 0.0 : value.value());
    }
  }
}
