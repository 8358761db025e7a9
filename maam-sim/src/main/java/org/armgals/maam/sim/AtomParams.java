package org.armgals.maam.sim;

/**
 * The physical parameters of every atom of a scene, in SI units: metres, kilograms, seconds,
 * radians, newtons, newton-metres, joules, watts. {@link #defaults()} is a 1:1 model of a small
 * atom; a scene may override any of them.
 *
 * @param kernelRadius radius of the spherical kernel (m)
 * @param kernelMass mass of the kernel (kg)
 * @param legLength length of a leg from the kernel's surface to the tip, caps included (m)
 * @param legRadius radius of a leg's capsule (m)
 * @param legMass mass of one leg (kg)
 * @param coneHalfAngle half-angle of the cone a leg moves in, from its rest axis (rad)
 * @param maxTorque torque limit of each of a leg's two motors (N·m)
 * @param maxSpeed speed limit of each motor (rad/s)
 * @param servoGain proportional gain of the position servo: commanded speed per radian of error
 *     (1/s)
 * @param batteryCapacity energy of a full battery (J)
 * @param idleDraw power drawn by the electronics whether or not the motors move (W)
 * @param motorEfficiency mechanical work out per electrical energy in, in (0, 1]
 * @param friction Coulomb friction coefficient of every contact
 * @param bindDistance largest distance between two tips that can bind (m)
 * @param bindAlignment largest angle between one leg and the reverse of the other that can bind
 *     (rad)
 * @param bindStrength largest force a binding holds before it breaks (N)
 * @param autoLock whether legs start locked, ready to bind to any locked tip that comes in
 *     tolerance (as a Webots Connector with autoLock)
 * @param proximityRange range of each leg's proximity ray, measured from the tip (m)
 */
public record AtomParams(
    double kernelRadius,
    double kernelMass,
    double legLength,
    double legRadius,
    double legMass,
    double coneHalfAngle,
    double maxTorque,
    double maxSpeed,
    double servoGain,
    double batteryCapacity,
    double idleDraw,
    double motorEfficiency,
    double friction,
    double bindDistance,
    double bindAlignment,
    double bindStrength,
    boolean autoLock,
    double proximityRange) {

  /** Checks every parameter, naming the first one out of range. */
  public AtomParams {
    positive("kernelRadius", kernelRadius);
    positive("kernelMass", kernelMass);
    positive("legLength", legLength);
    positive("legRadius", legRadius);
    if (2 * legRadius > legLength) {
      throw new IllegalArgumentException(
          "legRadius "
              + legRadius
              + " m is more than half of legLength "
              + legLength
              + " m: a leg must be at least as long as its two caps");
    }
    positive("legMass", legMass);
    if (!(coneHalfAngle > 0 && coneHalfAngle < Math.PI / 2)) {
      throw new IllegalArgumentException(
          "coneHalfAngle " + coneHalfAngle + " rad is not in (0, pi/2)");
    }
    positive("maxTorque", maxTorque);
    positive("maxSpeed", maxSpeed);
    positive("servoGain", servoGain);
    nonNegative("batteryCapacity", batteryCapacity);
    nonNegative("idleDraw", idleDraw);
    if (!(motorEfficiency > 0 && motorEfficiency <= 1)) {
      throw new IllegalArgumentException(
          "motorEfficiency " + motorEfficiency + " is not in (0, 1]");
    }
    nonNegative("friction", friction);
    positive("bindDistance", bindDistance);
    if (!(bindAlignment > 0 && bindAlignment <= Math.PI)) {
      throw new IllegalArgumentException(
          "bindAlignment " + bindAlignment + " rad is not in (0, pi]");
    }
    positive("bindStrength", bindStrength);
    positive("proximityRange", proximityRange);
  }

  /**
   * A small atom: a 5 cm kernel of 200 g, 6 cm legs of 20 g moving in a 30° cone, 0.5 N·m and 6
   * rad/s per motor, a 2 kJ battery with a 0.1 W idle draw, 5 mm / 10° binding tolerances and a 50
   * N binding, a 0.5 m proximity ray; no auto-lock.
   */
  public static AtomParams defaults() {
    return new AtomParams(
        0.05,
        0.2,
        0.06,
        0.01,
        0.02,
        Math.toRadians(30),
        0.5,
        6.0,
        20.0,
        2000.0,
        0.1,
        0.5,
        0.8,
        0.005,
        Math.toRadians(10),
        50.0,
        false,
        0.5);
  }

  /** The distance from the kernel's centre to a leg's tip at rest (m). */
  public double reach() {
    return kernelRadius + legLength;
  }

  private static void positive(String name, double value) {
    if (!(value > 0) || Double.isInfinite(value)) {
      throw new IllegalArgumentException(name + " " + value + " is not a finite positive number");
    }
  }

  private static void nonNegative(String name, double value) {
    if (!(value >= 0) || Double.isInfinite(value)) {
      throw new IllegalArgumentException(name + " " + value + " is not a finite number >= 0");
    }
  }
}
