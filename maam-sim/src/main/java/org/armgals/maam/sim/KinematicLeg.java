package org.armgals.maam.sim;

import org.armgals.maam.spi.Leg;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DRay;

/**
 * A leg as a capsule of its atom's one body, turned about its pivot by a servo that the world can
 * resist: the kinematic model ({@link LegDynamics#KINEMATIC}, decision 0029).
 *
 * <p>Each step the servo asks each axis for {@code clamp(servoGain · error, ±maxSpeed)}; the new
 * angles are brought back into the cone, and the capsule is placed at them. The world pushes back
 * through the torque its contacts and binding put on the leg about its pivot (its load, measured in
 * the previous step): an axis whose load exceeds the torque limit gives way, at a speed that grows
 * with the excess; a limp leg (motors off) gives way to any load. The leg's surface velocity goes
 * into its contacts, so a leg that sweeps its tip along the ground pushes the atom the other way,
 * within friction.
 */
final class KinematicLeg extends LegModel {

  private final DBody kernel;
  private final double[] axis1;

  /** Where the leg is on the kernel, at its angles. */
  private final LegPose pose;

  /** The leg's moment of inertia about its pivot (kg·m²), as a rod. */
  private final double inertia;

  private double a1;
  private double a2;
  private double rate1;
  private double rate2;
  private double load1;
  private double load2;
  private double loadX;
  private double loadY;
  private double loadZ;

  /** Whether {@link #pose} is that of the angles, and its turned axis 2 (which may be, alone). */
  private boolean posed;

  private boolean axis2Turned;

  /** Whether the capsule sits at the leg's pose on the kernel's body. */
  private boolean placed;

  KinematicLeg(AtomModel atom, Leg leg, DBody kernel, DCapsule capsule, DRay ray) {
    super(atom, leg, capsule, ray);
    this.kernel = kernel;
    AtomParams p = atom.params;
    this.pose = new LegPose(leg, p.kernelRadius(), p.legLength());
    this.axis1 = pose.axis1;
    // The angles start at 0: the rest pose, unworked.
    this.inertia = p.legMass() * p.legLength() * p.legLength() / 3;
  }

  /** The leg's pose, worked out for its angles if it is not yet. */
  private LegPose pose() {
    if (!posed) {
      pose.pose(a1, a2);
      posed = true;
      axis2Turned = true;
    }
    return pose;
  }

  /** Axis 2 as axis 1's turn has turned it. */
  private DVector3 turnedAxis2() {
    if (!axis2Turned) {
      pose.turnAxis2(a1);
      axis2Turned = true;
    }
    return pose.axis2();
  }

  /** Places the capsule on the kernel's body at the leg's pose, if it is not there yet. */
  @Override
  void place() {
    if (!placed) {
      capsule.setOffsetPosition(pose().centre());
      capsule.setOffsetQuaternion(pose().local());
      placed = true;
    }
  }

  /**
   * Writes a box in the kernel's frame that holds the capsule wherever it turns in its cone (see
   * {@link LegPose#coneBox}).
   */
  void coneBox(double[] to) {
    pose.coneBox(atom.params.coneHalfAngle(), atom.params.legRadius(), to);
  }

  /** Its parts hear of every move of the leg and of the kernel's body. */
  @Override
  boolean keepsItsRay() {
    return true;
  }

  @Override
  double angle1() {
    return a1;
  }

  @Override
  double angle2() {
    return a2;
  }

  @Override
  void servo(boolean motorsOn, double dt) {
    boolean on = motorsOn && powered && !failed;
    double w1 = rate(on, target1 - a1, load1);
    double w2 = rate(on, target2 - a2, load2);
    double r1 = 0;
    double r2 = 0;
    if (w1 != 0 || w2 != 0) {
      Cone cone = atom.cone;
      double n1 = cone.limit(settle(on, a1 + w1 * dt, target1));
      double n2 = cone.limit(settle(on, a2 + w2 * dt, target2));
      double f = cone.fit(n1, n2);
      if (f != 1) {
        n1 *= f;
        n2 *= f;
      }
      r1 = (n1 - a1) / dt;
      r2 = (n2 - a2) / dt;
      a1 = n1;
      a2 = n2;
      posed = false;
      axis2Turned = false;
      placed = false;
      atom.parts.moved(this);
    }
    double accel1 = (r1 - rate1) / dt;
    double accel2 = (r2 - rate2) / dt;
    rate1 = r1;
    rate2 = r2;
    double limit = on ? torqueLimit : 0;
    torque1 = clamp(inertia * accel1 - load1, limit);
    torque2 = clamp(inertia * accel2 - load2, limit);
    if (r1 != 0 || r2 != 0) {
      atom.turning |= bit;
    } else {
      atom.turning &= ~bit;
    }
    // Still, and still before: the next step would write the very same numbers, and does nothing
    // else, while what it reads stays as it is (see AtomModel.resting).
    if (atom.mayRest
        && w1 == 0
        && w2 == 0
        && accel1 == 0
        && accel2 == 0
        && !Double.isNaN(torque1)
        && !Double.isNaN(torque2)) {
      atom.resting |= bit;
    } else {
      atom.resting &= ~bit;
    }
    if (accel1 != 0 || accel2 != 0) {
      // The kernel takes the reaction of the torque that accelerates the leg (the legs' mass is
      // the body's, so nothing else would turn it back).
      double k1 = inertia * accel1;
      double k2 = inertia * accel2;
      double wakes = Physics.REST_ANGULAR * atom.turnInertia;
      boolean enabled = kernel.isEnabled();
      // The torque is no larger than |k1| + |k2| (the axes are unit vectors): when that is well
      // under what wakes a resting atom, the torque need not be worked out.
      if (enabled || (Math.abs(k1) + Math.abs(k2)) * (1 + 1e-9) * dt > wakes) {
        DVector3 turned = turnedAxis2();
        double tx = k1 * axis1[0] + k2 * turned.get0();
        double ty = k1 * axis1[1] + k2 * turned.get1();
        double tz = k1 * axis1[2] + k2 * turned.get2();
        if (!enabled && Math.sqrt(tx * tx + ty * ty + tz * tz) * dt > wakes) {
          // A reaction that would turn the resting atom faster than rest allows wakes it; a
          // smaller one is taken by what it rests on.
          kernel.enable();
        }
        if (kernel.isEnabled()) {
          kernel.addRelTorque(tx, ty, tz);
        }
      }
    }
  }

  /**
   * An axis that comes within {@link #SETTLED} of its target is at it: the servo's error shrinks by
   * a constant factor each step and would never reach zero, keeping the leg turning (and its atom
   * awake) for ever.
   */
  private static double settle(boolean on, double angle, double target) {
    return on && Math.abs(angle - target) <= SETTLED ? target : angle;
  }

  /**
   * The servo's resolution (rad): a microradian, a thousandth of a real servo's, moves the tip by a
   * tenth of a micrometre.
   */
  static final double SETTLED = 1e-6;

  /**
   * The speed an axis turns at (rad/s): the servo's, unless the load exceeds what the motor can
   * hold (nothing when its motors are off), then the load's way, faster the larger the excess.
   */
  private double rate(boolean on, double error, double load) {
    AtomParams p = atom.params;
    double excess = Math.abs(load) - (on ? torqueLimit : 0);
    if (excess > 0) {
      double speed = Math.min(p.maxSpeed(), p.servoGain() * excess / p.maxTorque());
      return Math.signum(load) * speed * yieldShare();
    }
    return on ? clamp(p.servoGain() * error, p.maxSpeed()) : 0;
  }

  /**
   * The share of its free speed at which an overloaded axis gives way: 1 for a free leg; for a
   * bound leg, its own inertia about the pivot over that of the leg and the bound atom it turns
   * with it (the atom's mass at the distance of its kernel from the pivot), so that a binding's
   * bodies are not thrown about by a reaction that comes a step late.
   */
  private double yieldShare() {
    Binding b = binding;
    if (b == null) {
      return 1;
    }
    AtomModel other = b.other(this).atom;
    AtomParams q = other.params;
    double mass = q.kernelMass() + Leg.values().length * q.legMass();
    double d = pivot().distance(other.kernel.getPosition());
    return inertia / (inertia + mass * d * d);
  }

  private static double clamp(double x, double limit) {
    return Math.max(-limit, Math.min(limit, x));
  }

  @Override
  void addLoad(double tx, double ty, double tz) {
    wake();
    loadX += tx;
    loadY += ty;
    loadZ += tz;
  }

  @Override
  void afterStep(double dt) {
    if (!kernel.isEnabled()) {
      // At rest: the engine did not solve the contacts, and the load is what it was.
      loadX = 0;
      loadY = 0;
      loadZ = 0;
      return;
    }
    DVector3 t = new DVector3();
    kernel.vectorFromWorld(loadX, loadY, loadZ, t);
    // Angles grow with negative turns about the axes.
    load1 = -(t.get0() * axis1[0] + t.get1() * axis1[1] + t.get2() * axis1[2]);
    load2 = -t.dot(turnedAxis2());
    loadX = 0;
    loadY = 0;
    loadZ = 0;
  }

  @Override
  double motorPower() {
    return Math.abs(torque1 * rate1) + Math.abs(torque2 * rate2);
  }

  @Override
  DBody carrier() {
    return kernel;
  }

  /** The leg's rotation in the kernel's frame (its local z is the leg's direction). */
  DQuaternionC localRotation() {
    return pose().local();
  }

  /** The tip in the kernel's frame. */
  DVector3 localTip() {
    return new DVector3(pose().tip());
  }

  /** Whether the leg turned in the last step. */
  boolean moved() {
    return rate1 != 0 || rate2 != 0;
  }

  @Override
  DVector3 direction() {
    DVector3 d = new DVector3();
    kernel.vectorToWorld(pose().direction(), d);
    return d;
  }

  @Override
  DVector3 tip() {
    DVector3 t = new DVector3();
    kernel.getRelPointPos(pose().tip(), t);
    return t;
  }

  @Override
  DVector3 pivot() {
    DVector3 p = new DVector3();
    kernel.getRelPointPos(pose.pivot(0), pose.pivot(1), pose.pivot(2), p);
    return p;
  }

  @Override
  boolean movesOnItsCarrier() {
    return moved();
  }

  @Override
  void velocityAt(DVector3C p, DVector3 out) {
    // The leg's angular velocity relative to the kernel, in the kernel's frame, then the world's.
    DVector3 turned = turnedAxis2();
    double wx = -(rate1 * axis1[0] + rate2 * turned.get0());
    double wy = -(rate1 * axis1[1] + rate2 * turned.get1());
    double wz = -(rate1 * axis1[2] + rate2 * turned.get2());
    DVector3 w = new DVector3();
    kernel.vectorToWorld(wx, wy, wz, w);
    DVector3 r = new DVector3(p).sub(pivot());
    out.set(
        w.get1() * r.get2() - w.get2() * r.get1(),
        w.get2() * r.get0() - w.get0() * r.get2(),
        w.get0() * r.get1() - w.get1() * r.get0());
  }
}
