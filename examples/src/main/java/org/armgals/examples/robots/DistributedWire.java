package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.List;
import org.armgals.active.Address;
import org.armgals.gals.Emission;

/**
 * What the world and the atoms of {@link Distributed} say to each other through the broker: the
 * records on both transports' allow-list, each carried in an {@link Emission}.
 */
final class DistributedWire {
  /** The allow-list of both sides. */
  static final Class<?>[] ALLOWED = {Emission.class, Joined.class, Readings.class, Commands.class};

  private DistributedWire() {}

  /**
   * An atom's runtime has joined: its robot's entity takes readings at {@code robot}.
   *
   * @param atom the atom's id in the scene
   * @param robot the address of the robot's reactive entity
   * @param pid the process the robot runs in
   * @param runtime the name of that process's runtime
   */
  public record Joined(int atom, Address robot, long pid, String runtime) {
    /** Checks the values. */
    public Joined {
      requireNonNull(robot, "robot");
      requireNonNull(runtime, "runtime");
    }
  }

  /**
   * What atom {@code atom}'s sensors read at the start of world cycle {@code cycle}; legs in {@link
   * org.armgals.maam.spi.Leg} order.
   *
   * @param timeNanos the world's simulated time of the cycle
   * @param elevations each leg's elevation in its cone, rad
   * @param azimuths each leg's azimuth around its cone's axis, rad
   * @param contacts whether each leg's tip touched something during the last period
   * @param roll the kernel's roll, rad
   * @param pitch the kernel's pitch, rad
   * @param battery the energy left, J
   */
  public record Readings(
      int atom,
      long cycle,
      long timeNanos,
      List<Double> elevations,
      List<Double> azimuths,
      List<Boolean> contacts,
      double roll,
      double pitch,
      double battery) {
    /** Checks that there is a value per leg. */
    public Readings {
      elevations = perLeg(elevations, "elevations");
      azimuths = perLeg(azimuths, "azimuths");
      contacts = perLeg(contacts, "contacts");
    }
  }

  /**
   * The leg targets atom {@code atom}'s robot commanded from the readings of world cycle {@code
   * cycle}; legs in {@link org.armgals.maam.spi.Leg} order, {@code NaN} for a leg not commanded.
   *
   * @param timeNanos the world's simulated time of the readings they answer
   * @param notified the sequence number of the last notification the robot's entity had sent its
   *     behavioral meta before the cycle that computed these commands (0: none): every notification
   *     of the readings before cycle {@code cycle}, and the world's lock step waits until its meta
   *     has handled them
   */
  public record Commands(
      int atom,
      long cycle,
      long timeNanos,
      List<Double> elevations,
      List<Double> azimuths,
      long notified) {
    /** Checks that there is a value per leg. */
    public Commands {
      elevations = perLeg(elevations, "elevations");
      azimuths = perLeg(azimuths, "azimuths");
      if (notified < 0) {
        throw new IllegalArgumentException(
            "notified " + notified + ": expected a sequence number >= 0");
      }
    }
  }

  private static <T> List<T> perLeg(List<T> values, String name) {
    requireNonNull(values, name);
    if (values.size() != 6) {
      throw new IllegalArgumentException(
          name + " has " + values.size() + " values: expected one per leg, 6");
    }
    return List.copyOf(values);
  }
}
