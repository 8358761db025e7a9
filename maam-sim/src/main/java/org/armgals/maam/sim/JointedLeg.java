package org.armgals.maam.sim;

import org.armgals.maam.spi.Leg;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DJoint.DJointFeedback;
import org.ode4j.ode.DRay;
import org.ode4j.ode.DUniversalJoint;

/**
 * A leg as a body of its own (a capsule) on a motorized universal joint on the kernel: the
 * articulated model ({@link LegDynamics#JOINTED}).
 */
final class JointedLeg extends LegModel {

  final DBody body;
  final DUniversalJoint joint;
  private final DJointFeedback feedback = new DJointFeedback();
  private final DVector3 anchor = new DVector3();
  private final DVector3 axis = new DVector3();
  private double rate1;
  private double rate2;

  JointedLeg(
      AtomModel atom, Leg leg, DBody body, DUniversalJoint joint, DCapsule capsule, DRay ray) {
    super(atom, leg, capsule, ray);
    this.body = body;
    this.joint = joint;
    joint.setFeedback(feedback);
  }

  /** Its body moves on its own, and no part tells when: the ray is aimed afresh every time. */
  @Override
  boolean keepsItsRay() {
    return false;
  }

  @Override
  double angle1() {
    return joint.getAngle1();
  }

  @Override
  double angle2() {
    return joint.getAngle2();
  }

  @Override
  DBody carrier() {
    return body;
  }

  @Override
  DVector3 pivot() {
    DVector3 p = new DVector3();
    joint.getAnchor(p);
    return p;
  }

  /**
   * One physics step of the servo: the stops of each axis follow the other axis's angle so the leg
   * stays in its cone, and each motor is asked for the speed that closes its error (within the
   * speed limit), which the solver reaches with no more than the torque limit.
   */
  @Override
  void servo(boolean motorsOn, double dt) {
    double a1 = joint.getAngle1();
    double a2 = joint.getAngle2();
    double s1 = atom.cone.stopGiven(a2);
    double s2 = atom.cone.stopGiven(a1);
    joint.setParam(DJoint.PARAM_N.dParamLoStop1, -s1);
    joint.setParam(DJoint.PARAM_N.dParamHiStop1, s1);
    joint.setParam(DJoint.PARAM_N.dParamLoStop2, -s2);
    joint.setParam(DJoint.PARAM_N.dParamHiStop2, s2);
    AtomParams p = atom.params;
    boolean on = motorsOn && powered && !failed;
    double fmax = on ? torqueLimit : 0;
    joint.setParam(DJoint.PARAM_N.dParamFMax1, fmax);
    joint.setParam(DJoint.PARAM_N.dParamFMax2, fmax);
    joint.setParam(DJoint.PARAM_N.dParamVel1, on ? speed(target1 - a1, p) : 0);
    joint.setParam(DJoint.PARAM_N.dParamVel2, on ? speed(target2 - a2, p) : 0);
  }

  private static double speed(double error, AtomParams p) {
    return Math.max(-p.maxSpeed(), Math.min(p.maxSpeed(), p.servoGain() * error));
  }

  /**
   * Reads the torques the joint applied to the leg about its two axes in the last step, about the
   * joint's anchor (so the reaction that holds the leg's weight is not counted as motor torque),
   * and the two angle rates.
   *
   * <p>The engine's quick-step (ode4j 0.5.3) leaves in the feedback's {@code f2}, {@code t2} the
   * force and torque (about its centre of mass) on the joint's first body, the kernel, and does not
   * fill {@code f1}, {@code t1}. The leg takes the opposite wrench: as a couple at the anchor,
   * {@code -(t2 - (anchor - kernel) x f2)}.
   */
  @Override
  void afterStep(double dt) {
    DVector3 anchor = this.anchor;
    joint.getAnchor(anchor);
    DVector3C com = atom.kernel.getPosition();
    double rx = anchor.get0() - com.get0();
    double ry = anchor.get1() - com.get1();
    double rz = anchor.get2() - com.get2();
    DVector3 f = feedback.f2;
    DVector3 t = feedback.t2;
    double jx = -(t.get0() - (ry * f.get2() - rz * f.get1()));
    double jy = -(t.get1() - (rz * f.get0() - rx * f.get2()));
    double jz = -(t.get2() - (rx * f.get1() - ry * f.get0()));
    joint.getAxis1(axis);
    torque1 = jx * axis.get0() + jy * axis.get1() + jz * axis.get2();
    joint.getAxis2(axis);
    torque2 = jx * axis.get0() + jy * axis.get1() + jz * axis.get2();
    rate1 = joint.getAngle1Rate();
    rate2 = joint.getAngle2Rate();
  }

  @Override
  double motorPower() {
    return Math.abs(torque1 * rate1) + Math.abs(torque2 * rate2);
  }

  @Override
  DVector3 direction() {
    DVector3 d = new DVector3();
    body.vectorToWorld(0, 0, 1, d);
    return d;
  }

  @Override
  DVector3 tip() {
    DVector3 d = direction();
    DVector3C c = body.getPosition();
    double half = atom.params.legLength() / 2;
    return new DVector3(
        c.get0() + d.get0() * half, c.get1() + d.get1() * half, c.get2() + d.get2() * half);
  }
}
