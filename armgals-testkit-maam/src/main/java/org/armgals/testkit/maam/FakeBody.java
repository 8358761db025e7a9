package org.armgals.testkit.maam;

import java.util.List;
import java.util.Optional;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Inbox;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.LegBinding;
import org.armgals.maam.spi.SensorKey;
import org.armgals.maam.spi.Tilt;

/**
 * The body test double: tests set what its sensors read and look at the commands its actuators
 * received. Every method is synchronized on the body, so a test thread and a robot's thread may
 * share one; the robot still sees one value per sensor and cycle only if the test sets sensors
 * between cycles. It keeps every command it receives until {@link #clearCommands}: a body for
 * tests, not for long runs.
 */
public sealed interface FakeBody extends Body permits FakeBodyImpl {

  /** A builder of a body named {@code id} with no sensor and no actuator yet. */
  static Builder builder(String id) {
    return new FakeBodyImpl.BuilderImpl(id);
  }

  /**
   * An atom: every sensor and actuator of {@link Atom}, legs on their axes, no contact, free,
   * nothing in range, level, {@code battery} joules, empty inbox.
   *
   * @throws IllegalArgumentException {@code battery} is negative or not finite
   */
  static FakeBody atom(String id, double battery) {
    if (!(battery >= 0 && battery < Double.POSITIVE_INFINITY)) {
      throw new IllegalArgumentException("battery " + battery + ": expected finite, >= 0");
    }
    Builder builder = builder(id);
    for (Leg leg : Leg.values()) {
      builder
          .sensor(Atom.angles(leg), LegAngles.AXIS)
          .sensor(Atom.contact(leg), false)
          .sensor(Atom.binding(leg), LegBinding.FREE)
          .sensor(Atom.proximity(leg), Double.POSITIVE_INFINITY)
          .actuator(Atom.target(leg))
          .actuator(Atom.torque(leg))
          .actuator(Atom.bind(leg));
    }
    return builder
        .sensor(Atom.TILT, Tilt.LEVEL)
        .sensor(Atom.BATTERY, battery)
        .sensor(Atom.INBOX, Inbox.EMPTY)
        .actuator(Atom.SEND)
        .build();
  }

  /**
   * Makes {@code sensor} read {@code value} from now on.
   *
   * @throws IllegalArgumentException no such sensor, or a value not of its type
   */
  <T> void set(SensorKey<T> sensor, T value);

  /**
   * Every command {@code actuator} received so far, oldest first.
   *
   * @throws IllegalArgumentException no such actuator
   */
  <T> List<T> commands(ActuatorKey<T> actuator);

  /** The last command {@code actuator} received, if any. */
  <T> Optional<T> lastCommand(ActuatorKey<T> actuator);

  /** How many times {@link #endCycle} was called. */
  long cycles();

  /** Forgets every command received so far. */
  void clearCommands();

  /** Declares the sensors and actuators of a {@link FakeBody}. Not thread-safe. */
  interface Builder {

    /**
     * Adds {@code sensor}, reading {@code initial} until set.
     *
     * @throws IllegalArgumentException a sensor of that name was already added
     */
    <T> Builder sensor(SensorKey<T> sensor, T initial);

    /**
     * Adds {@code actuator}.
     *
     * @throws IllegalArgumentException an actuator of that name was already added
     */
    Builder actuator(ActuatorKey<?> actuator);

    /** The body. */
    FakeBody build();
  }
}
