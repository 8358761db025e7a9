package org.armgals.maam.sim;

import org.ode4j.math.DQuaternion;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DFixedJoint;
import org.ode4j.ode.DJoint.DJointFeedback;
import org.ode4j.ode.OdeHelper;

/**
 * Two bound leg tips: a fixed joint between the bodies that carry them, whose feedback tells the
 * force it carries. Jointed legs are fixed to each other. Kinematic legs are part of their kernels,
 * so the joint fixes the two kernels, at the pose the two legs set: when either leg turns, the
 * joint is re-fixed so that the tips' frames keep the relative pose they had when they bound.
 */
final class Binding {

  final LegModel a;
  final LegModel b;
  private final DFixedJoint joint;
  private final DJointFeedback feedback = new DJointFeedback();

  /** The pose of b's tip frame in a's tip frame, when they bound (kinematic legs only). */
  private final DQuaternion tipTurn;

  private final DVector3 tipShift;

  Binding(Physics physics, LegModel a, LegModel b) {
    this.a = a;
    this.b = b;
    joint = OdeHelper.createFixedJoint(physics.world);
    a.carrier().enable();
    b.carrier().enable();
    joint.attach(a.carrier(), b.carrier());
    joint.setFixed();
    joint.setFeedback(feedback);
    a.binding = this;
    b.binding = this;
    a.atom.bound |= a.bit;
    b.atom.bound |= b.bit;
    if (a instanceof KinematicLeg ka && b instanceof KinematicLeg kb) {
      // tipA⁻¹ ∘ tipB, each tip frame the kernel's pose composed with the leg's local pose.
      DQuaternionC qa = Frames.multiply(ka.carrier().getQuaternion(), ka.localRotation());
      DQuaternionC qb = Frames.multiply(kb.carrier().getQuaternion(), kb.localRotation());
      DQuaternion inverseA = Frames.conjugate(qa);
      tipTurn = Frames.multiply(inverseA, qb);
      DVector3 d = kb.tip().sub(ka.tip());
      tipShift = Frames.rotate(inverseA, d.get0(), d.get1(), d.get2());
    } else {
      tipTurn = new DQuaternion(1, 0, 0, 0);
      tipShift = new DVector3();
    }
  }

  /**
   * Before a physics step: if a bound kinematic leg turned, re-fixes the joint at the kernels'
   * relative pose that the legs' angles now set, so the solver moves the atoms there.
   */
  void follow() {
    if (!(a instanceof KinematicLeg ka && b instanceof KinematicLeg kb)) {
      return;
    }
    if (!ka.moved() && !kb.moved()) {
      return;
    }
    // Where b's kernel belongs: kernelA ∘ legA ∘ (tipA⁻¹ ∘ tipB) ∘ legB⁻¹.
    DBody bodyA = ka.carrier();
    DBody bodyB = kb.carrier();
    DQuaternionC kernelA = bodyA.getQuaternion();
    DQuaternion tipA = Frames.multiply(kernelA, ka.localRotation());
    DQuaternion tipB = Frames.multiply(tipA, tipTurn);
    DQuaternion kernelB = Frames.multiply(tipB, Frames.conjugate(kb.localRotation()));
    DVector3 tipAt = ka.tip();
    DVector3 shift = Frames.rotate(tipA, tipShift.get0(), tipShift.get1(), tipShift.get2());
    DVector3 tipBLocal = kb.localTip();
    DVector3 tipBOffset =
        Frames.rotate(kernelB, tipBLocal.get0(), tipBLocal.get1(), tipBLocal.get2());
    DVector3 positionB = tipAt.add(shift).sub(tipBOffset);

    bodyA.enable();
    bodyB.enable();
    DVector3 savedPosition = new DVector3(bodyB.getPosition());
    DQuaternion savedTurn = new DQuaternion(bodyB.getQuaternion());
    bodyB.setPosition(positionB);
    bodyB.setQuaternion(kernelB);
    joint.setFixed();
    bodyB.setPosition(savedPosition);
    bodyB.setQuaternion(savedTurn);
    kb.atom.parts.bodyMoved();
  }

  /**
   * The force the binding carried in the last physics step (N); the engine fills in the second
   * body's side.
   */
  double force() {
    return feedback.f2.length();
  }

  /**
   * After a physics step: tells bound kinematic legs the torque the binding put on them about their
   * pivots (the joint's wrench on each kernel is carried through its leg). The engine's quick-step
   * (ode4j 0.5.3) leaves the wrench on the first body, about its centre, in {@code f2} and {@code
   * t2}; the second body takes the opposite force and the torque that balances both about its own
   * centre.
   */
  void loadLegs() {
    DVector3C f = feedback.f2;
    DVector3C t = feedback.t2;
    DVector3C comA = a.carrier().getPosition();
    DVector3C comB = b.carrier().getPosition();
    if (a instanceof KinematicLeg) {
      load(a, comA, f.get0(), f.get1(), f.get2(), t.get0(), t.get1(), t.get2());
    }
    if (b instanceof KinematicLeg) {
      // t_B = -t_A - (comA - comB) × f_A
      double rx = comA.get0() - comB.get0();
      double ry = comA.get1() - comB.get1();
      double rz = comA.get2() - comB.get2();
      load(
          b,
          comB,
          -f.get0(),
          -f.get1(),
          -f.get2(),
          -t.get0() - (ry * f.get2() - rz * f.get1()),
          -t.get1() - (rz * f.get0() - rx * f.get2()),
          -t.get2() - (rx * f.get1() - ry * f.get0()));
    }
  }

  /** Loads {@code leg} with the wrench (f, t) on its kernel, t about {@code com}. */
  private static void load(
      LegModel leg,
      DVector3C com,
      double fx,
      double fy,
      double fz,
      double tx,
      double ty,
      double tz) {
    DVector3 pivot = leg.pivot();
    double rx = com.get0() - pivot.get0();
    double ry = com.get1() - pivot.get1();
    double rz = com.get2() - pivot.get2();
    leg.addLoad(tx + ry * fz - rz * fy, ty + rz * fx - rx * fz, tz + rx * fy - ry * fx);
  }

  LegModel other(LegModel leg) {
    return leg == a ? b : a;
  }

  void release() {
    a.carrier().enable();
    b.carrier().enable();
    joint.destroy();
    a.binding = null;
    b.binding = null;
    a.atom.bound &= ~a.bit;
    b.atom.bound &= ~b.bit;
  }
}
