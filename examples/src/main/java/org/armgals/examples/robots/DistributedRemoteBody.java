package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.SensorKey;
import org.armgals.maam.spi.Tilt;
import org.jspecify.annotations.Nullable;

/**
 * An atom's body seen from another runtime: its sensors read the last {@link
 * DistributedWire.Readings} the world sent, and the leg targets the robot commands in a cycle
 * become one {@link DistributedWire.Commands}, tagged with the world cycle of the readings they
 * answer.
 *
 * <p>Threading: used by the thread of the robot's entity only (its reactions run one at a time);
 * {@link #feed} and {@link #takeCommands} are called from the robot's first and last modules.
 * {@link #worldTimeNanos} on any thread (the atom's kernel reads it as its time).
 */
final class DistributedRemoteBody implements Body {
  /** The world's simulated time of the readings, in ns; -1 before the first readings. */
  static final SensorKey<Long> WORLD_TIME = SensorKey.of("world.time", Long.class);

  private static final Set<SensorKey<?>> SENSORS = sensorKeys();
  private static final Set<ActuatorKey<?>> ACTUATORS = actuatorKeys();

  private final int atom;
  private final double[] elevations = new double[6];
  private final double[] azimuths = new double[6];
  private DistributedWire.@Nullable Readings readings;
  private volatile long worldTime = -1;
  private DistributedWire.@Nullable Readings answer;
  private List<Double> answerElevations = List.of();
  private List<Double> answerAzimuths = List.of();
  private long answered = -1;
  private boolean commanded;

  DistributedRemoteBody(int atom) {
    this.atom = atom;
    clearTargets();
  }

  /** The atom's id in the scene. */
  int atom() {
    return atom;
  }

  @Override
  public String id() {
    return "a" + atom;
  }

  @Override
  public Set<SensorKey<?>> sensors() {
    return SENSORS;
  }

  @Override
  public Set<ActuatorKey<?>> actuators() {
    return ACTUATORS;
  }

  /** Takes {@code next} as what the sensors read from the robot's next cycle. */
  void feed(DistributedWire.Readings next) {
    requireNonNull(next, "next");
    DistributedWire.Readings last = readings;
    if (last == null || next.cycle() > last.cycle()) {
      readings = next;
      worldTime = next.timeNanos();
    }
  }

  /** The world's simulated time of the last readings fed, in ns; -1 before any. */
  long worldTimeNanos() {
    return worldTime;
  }

  /**
   * The commands of the last cycle that answered new readings, once, telling that the robot had
   * sent its meta the notifications up to {@code notified}; null if there are none to send.
   */
  DistributedWire.@Nullable Commands takeCommands(long notified) {
    DistributedWire.Readings r = answer;
    if (r == null) {
      return null;
    }
    answer = null;
    return new DistributedWire.Commands(
        atom, r.cycle(), r.timeNanos(), answerElevations, answerAzimuths, notified);
  }

  @Override
  public <T> T read(SensorKey<T> sensor) {
    requireNonNull(sensor, "sensor");
    DistributedWire.Readings r = readings;
    if (sensor.equals(WORLD_TIME)) {
      return sensor.cast(r == null ? -1L : r.timeNanos());
    }
    if (sensor.equals(Atom.TILT)) {
      return sensor.cast(r == null ? Tilt.LEVEL : new Tilt(r.roll(), r.pitch()));
    }
    if (sensor.equals(Atom.BATTERY)) {
      return sensor.cast(r == null ? 0.0 : r.battery());
    }
    for (Leg leg : Leg.values()) {
      int i = leg.ordinal();
      if (sensor.equals(Atom.angles(leg))) {
        return sensor.cast(
            r == null ? LegAngles.AXIS : new LegAngles(r.elevations().get(i), r.azimuths().get(i)));
      }
      if (sensor.equals(Atom.contact(leg))) {
        return sensor.cast(r != null && r.contacts().get(i));
      }
    }
    throw new IllegalArgumentException(
        "atom " + id() + " has no sensor " + sensor + ": " + SENSORS);
  }

  @Override
  public <T> void command(ActuatorKey<T> actuator, T value) {
    requireNonNull(actuator, "actuator");
    requireNonNull(value, "value");
    for (Leg leg : Leg.values()) {
      if (actuator.equals(Atom.target(leg))) {
        LegAngles target = Atom.target(leg).cast(value);
        elevations[leg.ordinal()] = target.elevation();
        azimuths[leg.ordinal()] = target.azimuth();
        commanded = true;
        return;
      }
    }
    throw new IllegalArgumentException(
        "atom " + id() + " has no actuator " + actuator + ": " + ACTUATORS);
  }

  /** Makes the cycle's targets one message, if they answer readings not answered yet. */
  @Override
  public void endCycle() {
    DistributedWire.Readings r = readings;
    if (commanded && r != null && r.cycle() > answered) {
      answer = r;
      answerElevations = list(elevations);
      answerAzimuths = list(azimuths);
      answered = r.cycle();
    }
    clearTargets();
  }

  private void clearTargets() {
    Arrays.fill(elevations, Double.NaN);
    Arrays.fill(azimuths, Double.NaN);
    commanded = false;
  }

  private static List<Double> list(double[] values) {
    List<Double> out = new ArrayList<>(values.length);
    for (double v : values) {
      out.add(v);
    }
    return out;
  }

  private static Set<SensorKey<?>> sensorKeys() {
    Set<SensorKey<?>> keys = new LinkedHashSet<>();
    keys.add(WORLD_TIME);
    keys.add(Atom.TILT);
    keys.add(Atom.BATTERY);
    for (Leg leg : Leg.values()) {
      keys.add(Atom.angles(leg));
      keys.add(Atom.contact(leg));
    }
    return Set.copyOf(keys);
  }

  private static Set<ActuatorKey<?>> actuatorKeys() {
    Set<ActuatorKey<?>> keys = new LinkedHashSet<>();
    for (Leg leg : Leg.values()) {
      keys.add(Atom.target(leg));
    }
    return Set.copyOf(keys);
  }
}
