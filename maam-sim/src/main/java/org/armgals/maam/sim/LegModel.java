package org.armgals.maam.sim;

import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.jspecify.annotations.Nullable;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DRay;

/**
 * One leg: what every leg model shares (its commanded target, torque limit, connector, sensors and
 * proximity ray); how the leg moves is the subclass's: {@link JointedLeg} (a body on a motorized
 * universal joint) or {@link KinematicLeg} (geometry of the kernel's body, driven by its servo).
 */
abstract sealed class LegModel permits JointedLeg, KinematicLeg {

  final AtomModel atom;
  final Leg leg;

  /** The leg's bit in its atom's masks of legs: {@code 1 << ordinal}. */
  final int bit;

  final DCapsule capsule;

  /**
   * The engine's proximity ray: it lags where the ray was last placed until {@link #engineRay} sets
   * it, so it is read through that alone.
   */
  private final DRay ray;

  /** The torques the motors applied to the leg about its two axes in the last step (N·m). */
  double torque1;

  double torque2;

  /** The commanded angles (rad), within the cone. */
  double target1;

  double target2;

  /**
   * Whether the motors are on (until {@link #relax}); written through {@link #setTarget} and {@link
   * #relax}, which wake the servo.
   */
  boolean powered = true;

  /** Written through {@link #setTorqueLimit}, which wakes the servo. */
  double torqueLimit;

  /** Written through {@link #fail}, which wakes the servo. */
  boolean failed;

  boolean locked;
  @Nullable Binding binding;

  double proximity;

  /**
   * Whether the ray is where {@link #aimRay} would put it now: aimed since the leg last moved on
   * its carrier and the carrier last moved (see {@link Parts#moved} and {@link Parts#bodyMoved}).
   */
  boolean rayInPlace;

  LegModel(AtomModel atom, Leg leg, DCapsule capsule, DRay ray) {
    this.atom = atom;
    this.leg = leg;
    this.bit = 1 << leg.ordinal();
    this.capsule = capsule;
    this.ray = ray;
    this.torqueLimit = atom.params.maxTorque();
  }

  final void setTarget(double a1, double a2) {
    double[] fitted = new double[2];
    atom.cone.clamp(a1, a2, fitted);
    target1 = fitted[0];
    target2 = fitted[1];
    powered = true;
    wake();
  }

  /** Switches the motors off: the leg hangs limp until the next target. */
  final void relax() {
    powered = false;
    wake();
  }

  /** Limits the motors to {@code torque} (N·m). */
  final void setTorqueLimit(double torque) {
    torqueLimit = torque;
    wake();
  }

  /** The leg fails: it senses and moves no more. */
  final void fail() {
    failed = true;
    wake();
  }

  /**
   * Something the servo reads changed: it is no longer {@link AtomModel#resting at rest}, and works
   * out its next step.
   */
  final void wake() {
    atom.resting &= ~bit;
  }

  /** Whether the tip touched something during the current control period. */
  final boolean contact() {
    return (atom.contacts & bit) != 0;
  }

  /** The joint's angles of the last {@link #angles} asked for, and what they convert to. */
  private long readAngle1;

  private long readAngle2;
  private @Nullable LegAngles read;

  /**
   * {@link JointAngles#legAngles} of the joint's angles {@code (a1, a2)}, converted again only if
   * they are not those of the last reading (bit for bit): a leg that did not turn reads the very
   * same value (two arc tangents, a hypotenuse and four sines and cosines saved).
   */
  final LegAngles angles(double a1, double a2) {
    long bits1 = Double.doubleToRawLongBits(a1);
    long bits2 = Double.doubleToRawLongBits(a2);
    LegAngles last = read;
    if (last == null || bits1 != readAngle1 || bits2 != readAngle2) {
      last = JointAngles.legAngles(a1, a2);
      read = last;
      readAngle1 = bits1;
      readAngle2 = bits2;
    }
    return last;
  }

  /** The joint's first angle (rad). */
  abstract double angle1();

  /** The joint's second angle (rad). */
  abstract double angle2();

  /** One physics step of the servo, before the engine steps the world by {@code dt} seconds. */
  abstract void servo(boolean motorsOn, double dt);

  /** After the engine's step: reads the motors' torques and the angle rates of the step. */
  abstract void afterStep(double dt);

  /** Mechanical power of the two motors in the last step (W): |τ1·ω1| + |τ2·ω2|. */
  abstract double motorPower();

  /** The body a binding at this tip is fixed to. */
  abstract DBody carrier();

  /** The leg's unit direction in the world, in a vector of its own the caller may change. */
  abstract DVector3 direction();

  /** The tip's position: the end of the leg's far cap, in a vector of its own. */
  abstract DVector3 tip();

  /**
   * Whether the leg's surface moves relative to its {@link #carrier()} (then contacts on it take
   * {@link #velocityAt} as their surface velocity).
   */
  boolean movesOnItsCarrier() {
    return false;
  }

  /** The velocity of the leg's surface at {@code p} relative to its carrier, into {@code out}. */
  void velocityAt(DVector3C p, DVector3 out) {
    out.setZero();
  }

  /**
   * Adds the torque {@code (tx, ty, tz)} (world frame, N·m about the leg's pivot) that the world
   * applied to the leg in the last step through a contact or a binding.
   */
  void addLoad(double tx, double ty, double tz) {}

  /** The leg's pivot on the kernel's surface, in the world. */
  abstract DVector3 pivot();

  /** Puts the capsule where the leg is, for a collision. */
  void place() {}

  /**
   * Aims the proximity ray from the tip along the leg, unless it is already {@link #rayInPlace in
   * place}: aiming it again would write the very same numbers (decision 0080).
   */
  final void aimRay() {
    proximity = atom.params.proximityRange();
    if (!rayInPlace) {
      placeRay();
    }
  }

  /**
   * Writes where the ray is aimed from (the tip) and along (the leg), the box the engine would give
   * it, and its direction as the engine normalizes it, into its atom's {@link AtomModel#rays}. The
   * engine's ray is set from them only when it is cast at a geometry of the engine ({@link
   * #engineRay}): on a large grid, touching each ray's engine geometry at every sensing costs a
   * cache miss per ray, and most rays reach nothing or only the ground's plane, which {@link
   * Ground#rayOnPlane} meets without the engine (decision 0084).
   */
  final void placeRay() {
    double range = atom.params.proximityRange();
    DVector3 d = direction();
    DVector3 tip = tip();
    double[] rays = atom.rays;
    int at = AtomModel.RAY * leg.ordinal();
    rays[at] = tip.get0();
    rays[at + 1] = tip.get1();
    rays[at + 2] = tip.get2();
    rays[at + 3] = d.get0();
    rays[at + 4] = d.get1();
    rays[at + 5] = d.get2();
    // As the engine sets a ray (DxRay.dGeomRaySet), with the direction this call's own vector.
    DVector3 unit = d.normalize();
    int box = at + AtomModel.RAY_BOX;
    for (int axis = 0; axis < 3; axis++) {
      double from = rays[at + axis];
      double u = unit.get(axis);
      rays[at + AtomModel.RAY_UNIT + axis] = u;
      // The engine's box of a ray (DxRay.computeAABB): its start, and its start plus its length
      // along it.
      double to = u * range + from;
      rays[box + 2 * axis] = from < to ? from : to;
      rays[box + 2 * axis + 1] = from < to ? to : from;
    }
    engineRayBehind = true;
    rayInPlace = keepsItsRay();
  }

  /** Whether the engine's ray lags where the ray was last {@link #placeRay placed}. */
  private boolean engineRayBehind;

  /**
   * The engine's ray, set where the ray was last {@link #placeRay placed} if it lags: for a
   * collider. Only the thread that places the leg's ray calls it.
   */
  final DRay engineRay() {
    if (engineRayBehind) {
      double[] rays = atom.rays;
      int at = AtomModel.RAY * leg.ordinal();
      ray.set(rays[at], rays[at + 1], rays[at + 2], rays[at + 3], rays[at + 4], rays[at + 5]);
      ray.setLength(atom.params.proximityRange());
      engineRayBehind = false;
    }
    return ray;
  }

  /** Destroys the engine's ray, with the simulation. */
  final void destroyRay() {
    ray.destroy();
  }

  /**
   * Whether the ray, once aimed, stays in place until its atom's {@link Parts} hear that the leg or
   * the carrier moved.
   */
  abstract boolean keepsItsRay();
}
