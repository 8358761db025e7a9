package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.List;
import org.armgals.maam.spi.Leg;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DMass;
import org.ode4j.ode.DRay;
import org.ode4j.ode.DRotation;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DSphere;
import org.ode4j.ode.DUniversalJoint;
import org.ode4j.ode.OdeHelper;

/**
 * One atom's physics and state: kernel, six legs, battery, failure, inbox, pending push. With
 * {@link LegDynamics#KINEMATIC} legs the kernel's body carries the whole atom's mass (the legs' at
 * their rest pose); with {@link LegDynamics#JOINTED} legs it carries the kernel's alone.
 */
final class AtomModel {

  final int id;
  final AtomParams params;
  final Cone cone;

  final DBody kernel;

  /** The legs, in the order of {@link Leg}. */
  final LegModel[] legs = new LegModel[Leg.values().length];

  /**
   * The atom's kernel and leg capsules as the broad phase sees them; they are never tested against
   * each other.
   */
  final Parts parts;

  /** The kernel's up axis at the start, in the kernel's frame: what tilt is measured from. */
  private final DVector3 upLocal;

  /** The smallest moment of inertia of the kernel's body (kg·m²). */
  final double turnInertia;

  /**
   * The atom rests (the engine does not step its body) and no leg of it moved this step: its
   * collisions with the world and other still atoms are skipped.
   */
  boolean still;

  /** The atom's place in the simulation's list (and the broad phase's), in id order. */
  final int index;

  double energy;
  boolean failed;
  boolean emptyReported;

  /** The messages that arrived at the start of the current control cycle. */
  final List<ReceivedMessage> inbox = new ArrayList<>();

  double pushX;
  double pushY;
  double pushZ;

  /**
   * The legs' proximity rays side by side, leg l's at {@code RAY * l}: where it was last aimed from
   * (the tip) and along (the leg's direction), then its box (at {@code RAY_BOX}, see {@link
   * Boxes}), then its direction as the engine normalizes it (at {@code RAY_UNIT}). Casting reads
   * them here, not from the legs and the engine's rays (decisions 0080 and 0084).
   */
  final double[] rays = new double[RAY * Leg.values().length];

  static final int RAY = 15;
  static final int RAY_BOX = 6;
  static final int RAY_UNIT = 12;

  /** A bit per leg, by ordinal: its ray is aimed, to be cast in this cycle's sensing pass. */
  int aimed;

  // The legs' state that every step reads, a bit per leg by ordinal, here rather than in the legs:
  // with a thousand atoms, each step reads them from memory afresh, and a leg that rests is then
  // not read at all (decision 0080).

  /** The tip touched something during the current control period. */
  int contacts;

  /**
   * The tip touched another atom in the last step whose collisions with other atoms were computed
   * for this atom.
   */
  int touchingAtoms;

  /**
   * The tip touched the ground or an obstacle in the last step whose collisions with them were
   * computed for this atom.
   */
  int touchingGrounds;

  /** The leg turned on its carrier in the last step (see {@link LegModel#movesOnItsCarrier}). */
  int turning;

  /** The leg is bound. */
  int bound;

  /**
   * The leg's servo is at rest: its last step left every number as it was, and so will the next
   * while nothing it reads changes (its target, power, torque limit, failure or load, the atom's
   * motors or the kernel's rest), and its load is nought; so its servo, the reading of its load and
   * its power (nought) are skipped until it is {@link LegModel#wake woken}. Only kinematic legs
   * rest.
   */
  int resting;

  /** Whether legs may rest (see {@link #resting}); off only in the test that holds both ways. */
  boolean mayRest = true;

  /**
   * The atom placed at {@code placement}, at {@code index} in the simulation's list; {@code cone}
   * is {@code params}' (one for every atom that shares them).
   */
  AtomModel(
      Physics physics,
      int index,
      Scene.Placement placement,
      AtomParams params,
      Cone cone,
      LegDynamics dynamics) {
    this.index = index;
    this.id = placement.id();
    this.params = params;
    this.cone = cone;
    this.energy = params.batteryCapacity();
    DQuaternion q = Frames.of(placement.orientation());
    Vec3 c = placement.position();
    DQuaternion inverse = new DQuaternion(q.get0(), -q.get1(), -q.get2(), -q.get3());
    upLocal = Frames.rotate(inverse, 0, 0, 1);

    kernel = OdeHelper.createBody(physics.world);
    kernel.setPosition(c.x(), c.y(), c.z());
    kernel.setQuaternion(q);
    // Jointed legs' parts in a space of the engine's, which keeps their order; kinematic legs'
    // parts in none (KinematicParts keeps it).
    DSpace space = dynamics == LegDynamics.JOINTED ? OdeHelper.createSimpleSpace() : null;
    DSphere sphere = OdeHelper.createSphere(space, params.kernelRadius());
    sphere.setBody(kernel);
    sphere.setData(new GeomTag(GeomTag.Kind.KERNEL, this, null));
    DMass mass = OdeHelper.createMass();
    mass.setSphereTotal(params.kernelMass(), params.kernelRadius());
    double cylinder = params.legLength() - 2 * params.legRadius();
    for (Leg leg : Leg.values()) {
      // A proximity ray, in no space: cast only while the sensors are read.
      DRay ray = OdeHelper.createRay(null, params.proximityRange());
      DCapsule capsule = OdeHelper.createCapsule(space, params.legRadius(), cylinder);
      LegModel model =
          switch (dynamics) {
            case JOINTED -> jointedLeg(physics, leg, q, c, capsule, ray);
            case KINEMATIC -> {
              capsule.setBody(kernel);
              mass.add(restLegMass(leg));
              yield new KinematicLeg(this, leg, kernel, capsule, ray);
            }
          };
      model.locked = params.autoLock();
      model.proximity = params.proximityRange();
      capsule.setData(new GeomTag(GeomTag.Kind.LEG, this, model));
      legs[leg.ordinal()] = model;
    }
    if (space != null) {
      parts = new SpaceParts(space, legs.length + 1);
    } else {
      KinematicLeg[] kinematic = new KinematicLeg[legs.length];
      for (LegModel leg : legs) {
        kinematic[leg.leg.ordinal()] = (KinematicLeg) leg;
      }
      parts = new KinematicParts(kernel, sphere, params.kernelRadius(), kinematic, params.reach());
    }
    // The legs sit symmetrically, so the centre of mass is the kernel's centre up to rounding; the
    // engine wants it exactly there.
    DVector3 offCentre = new DVector3(mass.getC()).scale(-1);
    mass.translate(offCentre);
    kernel.setMass(mass);
    turnInertia = Math.min(mass.getI().get00(), Math.min(mass.getI().get11(), mass.getI().get22()));
    if (dynamics == LegDynamics.KINEMATIC) {
      Physics.restWhenStill(kernel);
    }
  }

  /** A leg's mass and inertia at its rest pose, in the kernel's frame. */
  private DMass restLegMass(Leg leg) {
    double cylinder = params.legLength() - 2 * params.legRadius();
    DMass legMass = OdeHelper.createMass();
    legMass.setCapsuleTotal(params.legMass(), 3, params.legRadius(), cylinder);
    DMatrix3 r = new DMatrix3();
    DRotation.dRfromQ(r, Frames.zOnto(leg));
    legMass.rotate(r);
    double d = params.kernelRadius() + params.legLength() / 2;
    legMass.translate(leg.x() * d, leg.y() * d, leg.z() * d);
    return legMass;
  }

  /** A leg body on a universal joint at the kernel's surface, its capsule on it. */
  private JointedLeg jointedLeg(
      Physics physics, Leg leg, DQuaternion q, Vec3 c, DCapsule capsule, DRay ray) {
    double r = params.kernelRadius();
    double half = params.legLength() / 2;
    double cylinder = params.legLength() - 2 * params.legRadius();
    DVector3 d = Frames.rotate(q, leg.x(), leg.y(), leg.z());
    DBody body = OdeHelper.createBody(physics.world);
    DMass legMass = OdeHelper.createMass();
    legMass.setCapsuleTotal(params.legMass(), 3, params.legRadius(), cylinder);
    body.setMass(legMass);
    body.setPosition(
        c.x() + d.get0() * (r + half),
        c.y() + d.get1() * (r + half),
        c.z() + d.get2() * (r + half));
    body.setQuaternion(Frames.multiply(q, Frames.zOnto(leg)));
    capsule.setBody(body);

    DUniversalJoint joint = OdeHelper.createUniversalJoint(physics.world);
    joint.attach(kernel, body);
    joint.setAnchor(c.x() + d.get0() * r, c.y() + d.get1() * r, c.z() + d.get2() * r);
    double[] a1 = Frames.axis1(leg);
    double[] a2 = Frames.axis2(leg);
    joint.setAxis1(Frames.rotate(q, a1[0], a1[1], a1[2]));
    joint.setAxis2(Frames.rotate(q, a2[0], a2[1], a2[2]));
    return new JointedLeg(this, leg, body, joint, capsule, ray);
  }

  /**
   * Before the step's collisions: decides whether the atom is {@link #still}; a still atom's tips
   * keep touching what they touched, a moving atom's are found again (those with the ground and
   * obstacles as {@link Physics} decides).
   */
  void beforeCollisions() {
    still = !kernel.isEnabled() && turning == 0;
    if (still) {
      contacts |= touchingAtoms | touchingGrounds;
    } else {
      touchingAtoms = 0;
    }
  }

  /** After the engine's step: a body it stepped has moved its parts. */
  void stepped() {
    if (kernel.isEnabled()) {
      parts.bodyMoved();
    }
  }

  LegModel leg(Leg leg) {
    return legs[leg.ordinal()];
  }

  boolean motorsOn() {
    return !failed && energy > 0;
  }

  /** The angle between the kernel's up axis now and at the start (rad). */
  double tilt() {
    DVector3 up =
        Frames.rotate(kernel.getQuaternion(), upLocal.get0(), upLocal.get1(), upLocal.get2());
    return Math.acos(Math.max(-1, Math.min(1, up.get2())));
  }

  Vec3 position() {
    DVector3C p = kernel.getPosition();
    return new Vec3(p.get0(), p.get1(), p.get2());
  }

  Quat orientation() {
    DQuaternionC q = kernel.getQuaternion();
    double n = q.length();
    return new Quat(q.get0() / n, q.get1() / n, q.get2() / n, q.get3() / n);
  }

  /**
   * Drains the battery for one physics step of {@code dt} seconds: the idle draw plus the motors'
   * mechanical power over their efficiency. Returns true the step it runs empty.
   */
  boolean drain(double dt) {
    if (kernel.isEnabled()) {
      // The engine stepped the kernel, and its contacts load every leg afresh.
      resting = 0;
    }
    int awake = ~resting;
    for (int l = 0; l < legs.length; l++) {
      if ((awake & 1 << l) != 0) {
        legs[l].afterStep(dt);
      }
    }
    if (failed || energy <= 0) {
      return false;
    }
    double power = params.idleDraw();
    for (int l = 0; l < legs.length; l++) {
      // A resting leg's power is nought, and adding it would leave the sum as it is.
      if ((awake & 1 << l) != 0 && !legs[l].failed) {
        power += legs[l].motorPower() / params.motorEfficiency();
      }
    }
    energy = Math.max(0, energy - power * dt);
    if (energy == 0) {
      // The motors stop.
      resting = 0;
      return true;
    }
    return false;
  }

  /** The atom fails: it senses, moves and drains no more. */
  void fail() {
    failed = true;
    resting = 0;
  }
}
