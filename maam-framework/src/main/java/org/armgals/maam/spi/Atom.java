package org.armgals.maam.spi;

import static java.util.Objects.requireNonNull;

import java.util.EnumMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/**
 * The sensors and actuators of a MAAM atom, by name and type: a body that is an atom has at least
 * these. Per leg ({@code leg.<leg>.<what>}, {@code <leg>} being {@link Leg#key}):
 *
 * <ul>
 *   <li>sensors: {@link #angles} ({@link LegAngles}), {@link #contact} (leg tip touches something),
 *       {@link #binding} ({@link LegBinding}), {@link #proximity} (metres to the nearest obstacle
 *       along the leg, {@link Double#POSITIVE_INFINITY} when none in range);
 *   <li>actuators: {@link #target} ({@link LegAngles} to move to), {@link #torque} (the most the
 *       leg's motors may exert, N·m, a level), {@link #bind} ({@link BindCommand}, an event).
 * </ul>
 *
 * <p>For the whole atom: sensors {@link #TILT}, {@link #BATTERY} (energy left, joules) and {@link
 * #INBOX}; actuator {@link #SEND} (one {@link NeighbourMessage} per command).
 */
public final class Atom {

  /** The atom's attitude. */
  public static final SensorKey<Tilt> TILT = SensorKey.of("tilt", Tilt.class);

  /** Energy left in the battery, joules. */
  public static final SensorKey<Double> BATTERY = SensorKey.of("battery", Double.class);

  /** Messages from bound neighbours since the previous cycle. */
  public static final SensorKey<Inbox> INBOX = SensorKey.of("inbox", Inbox.class);

  /** Sends one message to the neighbour bound to the message's leg. */
  public static final ActuatorKey<NeighbourMessage> SEND =
      ActuatorKey.of("send", NeighbourMessage.class);

  private static final Map<Leg, SensorKey<LegAngles>> ANGLES = perLeg("angles", LegAngles.class);
  private static final Map<Leg, SensorKey<Boolean>> CONTACT = perLeg("contact", Boolean.class);
  private static final Map<Leg, SensorKey<LegBinding>> BINDING =
      perLeg("binding", LegBinding.class);
  private static final Map<Leg, SensorKey<Double>> PROXIMITY = perLeg("proximity", Double.class);
  private static final Map<Leg, ActuatorKey<LegAngles>> TARGET =
      perLegActuator("target", LegAngles.class);
  private static final Map<Leg, ActuatorKey<Double>> TORQUE =
      perLegActuator("torque", Double.class);
  private static final Map<Leg, ActuatorKey<BindCommand>> BIND =
      perLegActuator("bind", BindCommand.class);

  private Atom() {}

  /** Where {@code leg} points. */
  public static SensorKey<LegAngles> angles(Leg leg) {
    return ANGLES.get(requireNonNull(leg, "leg"));
  }

  /** Whether {@code leg}'s tip touches something. */
  public static SensorKey<Boolean> contact(Leg leg) {
    return CONTACT.get(requireNonNull(leg, "leg"));
  }

  /** What {@code leg}'s tip is bound to. */
  public static SensorKey<LegBinding> binding(Leg leg) {
    return BINDING.get(requireNonNull(leg, "leg"));
  }

  /** Metres to the nearest obstacle along {@code leg}; infinite when none in range. */
  public static SensorKey<Double> proximity(Leg leg) {
    return PROXIMITY.get(requireNonNull(leg, "leg"));
  }

  /** Where {@code leg} should move to. */
  public static ActuatorKey<LegAngles> target(Leg leg) {
    return TARGET.get(requireNonNull(leg, "leg"));
  }

  /** The most torque {@code leg}'s motors may exert, N·m, not negative. */
  public static ActuatorKey<Double> torque(Leg leg) {
    return TORQUE.get(requireNonNull(leg, "leg"));
  }

  /** Bind or release {@code leg}'s tip. */
  public static ActuatorKey<BindCommand> bind(Leg leg) {
    return BIND.get(requireNonNull(leg, "leg"));
  }

  /** Every sensor of an atom, legs first in {@link Leg} order, then tilt, battery and inbox. */
  public static Set<SensorKey<?>> sensors() {
    return All.SENSORS;
  }

  private static Set<SensorKey<?>> allSensors() {
    Set<SensorKey<?>> all = new LinkedHashSet<>();
    for (Leg leg : Leg.values()) {
      all.add(angles(leg));
      all.add(contact(leg));
      all.add(binding(leg));
      all.add(proximity(leg));
    }
    all.add(TILT);
    all.add(BATTERY);
    all.add(INBOX);
    return java.util.Collections.unmodifiableSet(all);
  }

  /** Every actuator of an atom, legs first in {@link Leg} order, then send. */
  public static Set<ActuatorKey<?>> actuators() {
    return All.ACTUATORS;
  }

  /**
   * The sets of every sensor and actuator, made once: a body checks each command against them,
   * every cycle.
   */
  private static final class All {
    static final Set<SensorKey<?>> SENSORS = allSensors();
    static final Set<ActuatorKey<?>> ACTUATORS = allActuators();
  }

  private static Set<ActuatorKey<?>> allActuators() {
    Set<ActuatorKey<?>> all = new LinkedHashSet<>();
    for (Leg leg : Leg.values()) {
      all.add(target(leg));
      all.add(torque(leg));
      all.add(bind(leg));
    }
    all.add(SEND);
    return java.util.Collections.unmodifiableSet(all);
  }

  private static <T> Map<Leg, SensorKey<T>> perLeg(String what, Class<T> type) {
    Map<Leg, SensorKey<T>> keys = new EnumMap<>(Leg.class);
    for (Leg leg : Leg.values()) {
      keys.put(leg, SensorKey.of("leg." + leg.key() + "." + what, type));
    }
    return keys;
  }

  private static <T> Map<Leg, ActuatorKey<T>> perLegActuator(String what, Class<T> type) {
    Map<Leg, ActuatorKey<T>> keys = new EnumMap<>(Leg.class);
    for (Leg leg : Leg.values()) {
      keys.put(leg, ActuatorKey.of("leg." + leg.key() + "." + what, type));
    }
    return keys;
  }
}
