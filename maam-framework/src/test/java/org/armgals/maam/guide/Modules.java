package org.armgals.maam.guide;

import java.util.List;
import org.armgals.maam.Actuator;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.guide.Signals.LowBattery;
import org.armgals.maam.guide.Signals.Stance;
import org.armgals.maam.guide.Signals.Tilted;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.Tilt;

/** Step 2: the balancing atom's behavior modules. */
final class Modules {

  private Modules() {}

  static final Port<Tilted> TILTED = Port.of("tilted", Tilted.class);
  static final Port<LowBattery> LOW = Port.of("low", LowBattery.class);
  static final Port<Stance> STANCE = Port.of("stance", Stance.class);

  // tag::perceptor[]
  /**
   * Emits a stimulus when the atom leans more than {@code threshold} radians, nothing otherwise.
   */
  record TiltSensor(String name, double threshold) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(TILTED);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      Tilt tilt = body.read(Atom.TILT);
      if (Math.abs(tilt.roll()) > threshold || Math.abs(tilt.pitch()) > threshold) {
        out.emit(TILTED, new Tilted(tilt.roll(), tilt.pitch()));
      }
    }
  }

  // end::perceptor[]

  /** Emits a stimulus when the battery holds less than {@code joules}. */
  record BatterySensor(String name, double joules) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(LOW);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      double left = body.read(Atom.BATTERY);
      if (left < joules) {
        out.emit(LOW, new LowBattery(left));
      }
    }
  }

  // tag::reactor[]
  /** Opens the legs in proportion to the lean; stands narrow when level. */
  record Balance(String name, double gain) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(TILTED);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STANCE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Tilted tilted = in.get(TILTED); // null: no stimulus this cycle
      double lean =
          tilted == null ? 0 : Math.max(Math.abs(tilted.roll()), Math.abs(tilted.pitch()));
      out.emit(STANCE, new Stance(Math.min(1.2, 0.2 + gain * lean)));
    }
  }

  // end::reactor[]

  /** Folds the legs to rest while the battery is low. */
  record Rest(String name) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(LOW);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STANCE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      if (in.get(LOW) != null) {
        out.emit(STANCE, new Stance(0));
      }
    }
  }

  // tag::actuator[]
  /** Sends the stance to the six legs. */
  record LegDrive(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(STANCE);
    }

    @Override
    public void act(Inputs in, Body body) {
      Stance stance = in.get(STANCE);
      if (stance != null) {
        for (Leg leg : Leg.values()) {
          body.command(Atom.target(leg), new LegAngles(stance.elevation(), 0));
        }
      }
    }
  }
  // end::actuator[]
}
