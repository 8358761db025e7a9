package org.armgals.examples.robots;

/**
 * A gait of the {@link EnergySaver} atom: every leg's tip turns round its cone at {@code stroke}
 * radians from the cone's axis, each leg a third of a turn after the previous one, so the stance
 * legs push the kernel along. The two gaits, and every physical constant of the robot, are here.
 *
 * @param name how the journal and the summary call it
 * @param stroke elevation of every leg from its cone's axis, rad (the cone is 30°, 0.52 rad)
 * @param frequency turns per second of the tips, when the legs keep up
 * @param torqueLimit every motor's torque limit, N·m (the atom's own limit is 0.5)
 */
record EnergyGait(String name, double stroke, double frequency, double torqueLimit) {

  /**
   * Middling strokes, fast, at full torque: it goes, and drains the battery. (Wider strokes go no
   * further: the tips turning round the cone's edge at 2 turns a second outrun the servos.)
   */
  static final EnergyGait FAST = new EnergyGait("fast", 0.35, 3.0, 0.5);

  /**
   * Small strokes, slow: it crawls, and lasts. At full torque too: a leg held under the weight it
   * carries gives way and pushes the atom back up, turn after turn, which costs more than it saves
   * (at 0.1 N·m the same gait draws twice as much).
   */
  static final EnergyGait SAVING = new EnergyGait("saving", 0.25, 1.0, 0.5);

  /** Phase between two legs, in the framework's leg order: a third of a turn. */
  static final double LEG_LAG = 2 * Math.PI / 3;

  /** Phase of the first leg at the start. */
  static final double START_PHASE = 1.0;

  /**
   * The gait waits for the legs while their tips are farther than this fraction of the stroke from
   * where they were sent: it runs as fast as the motors follow.
   */
  static final double TRACKING_TOLERANCE = 0.6;

  /** Checks the ranges. */
  EnergyGait {
    if (!(stroke > 0 && stroke < Math.PI / 6 + 1e-9)) {
      throw new IllegalArgumentException("stroke " + stroke + " rad: expected in (0, π/6]");
    }
    if (!(frequency > 0)) {
      throw new IllegalArgumentException("frequency " + frequency + " Hz: expected > 0");
    }
    if (!(torqueLimit > 0)) {
      throw new IllegalArgumentException("torqueLimit " + torqueLimit + " N·m: expected > 0");
    }
  }
}
