package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import org.jspecify.annotations.Nullable;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DContact;
import org.ode4j.ode.DContactBuffer;
import org.ode4j.ode.DContactJoint;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DJoint.DJointFeedback;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DMisc;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeConstants;
import org.ode4j.ode.OdeHelper;
import org.ode4j.ode.OdeMath;
import org.ode4j.ode.internal.ErrorHdl;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine's world: gravity, ground, obstacles, collisions and contacts, stepped in fixed steps.
 * The engine keeps one global (the seed of the random order its solver visits constraints in); each
 * step swaps this world's seed in under a lock, so worlds stepped on several threads stay
 * deterministic.
 */
final class Physics {

  private static final ReentrantLock ENGINE = new ReentrantLock();
  private static final int MAX_CONTACTS = 4;

  /**
   * Iterations of the engine's iterative solver per step: 10 holds joints and contacts well at 1 ms
   * with atoms of a few hundred grams, at half the cost of the engine's default 20.
   */
  private static final int SOLVER_ITERATIONS = 10;

  /**
   * A body whose speeds, averaged over {@link #REST_SAMPLES} steps, stay below these for {@link
   * #REST_STEPS} steps is at rest: the engine stops stepping it until something wakes it (a contact
   * with a moving body, a push, a leg that moves where it touches, a binding).
   */
  static final double REST_LINEAR = 0.002;

  /** See {@link #REST_LINEAR} (rad/s). */
  static final double REST_ANGULAR = 0.02;

  private static final int REST_STEPS = 20;
  private static final int REST_SAMPLES = 10;

  /** Lets the engine stop stepping {@code body} while it rests (see {@link #REST_LINEAR}). */
  static void restWhenStill(DBody body) {
    body.setAutoDisableLinearThreshold(REST_LINEAR);
    body.setAutoDisableAngularThreshold(REST_ANGULAR);
    body.setAutoDisableSteps(REST_STEPS);
    body.setAutoDisableTime(0);
    body.setAutoDisableAverageSamplesCount(REST_SAMPLES);
    body.setAutoDisableFlag(true);
  }

  private static final Logger LOG = LoggerFactory.getLogger(Physics.class);

  static {
    OdeHelper.initODE2(0);
    // The engine's informational messages (e.g. "zero length vector" while a universal joint's
    // first axis is set before its second) are debug output, not news for users.
    ErrorHdl.dSetMessageHandler(
        (num, format, args) -> LOG.debug("ode4j message {}: {}", num, format));
  }

  final DWorld world;

  /** Which pairs the near callback looks at. */
  private final BroadPhase broadPhase;

  private final DJointGroup contacts = OdeHelper.createJointGroup();
  private final DContactBuffer buffer = new DContactBuffer(MAX_CONTACTS);
  private final double friction;
  private final double legRadius;
  private long seed;

  /** The world of {@code scene}, its solver seeded with {@code seed}, sensing on {@code lanes}. */
  Physics(Scene scene, long seed, int lanes) {
    this.seed = seed & 0xffffffffL;
    this.friction = scene.params().friction();
    this.legRadius = scene.params().legRadius();
    world = OdeHelper.createWorld();
    Vec3 g = scene.gravity();
    world.setGravity(g.x(), g.y(), g.z());
    world.setERP(0.2);
    world.setCFM(1e-6);
    world.setQuickStepNumIterations(SOLVER_ITERATIONS);
    world.setContactMaxCorrectingVel(1.0);
    world.setContactSurfaceLayer(0.0005);
    broadPhase = new BroadPhase(new Ground(scene.obstacles()), nearCallback, lanes);
  }

  /** Adds an atom; atoms are added in id order. */
  void add(AtomModel atom) {
    broadPhase.add(atom);
  }

  /**
   * Readies {@code atom} for rays cast on several lanes, after it is {@link #file filed}: see
   * {@link Parts#readyForRays}.
   */
  void readyForRays(AtomModel atom) {
    atom.parts.readyForRays();
  }

  /** Every atom filed (and readied), before the lanes cast: see {@link BroadPhase#fileForRays}. */
  void fileForRays() {
    broadPhase.fileForRays();
  }

  /**
   * Casts {@code atom}'s aimed rays on lane {@code lane}: see {@link BroadPhase#castRays(int,
   * AtomModel)}.
   */
  void castRays(int lane, AtomModel atom) {
    broadPhase.castRays(lane, atom);
  }

  /** Files {@code atom} for a sensing pass: see {@link BroadPhase#file}. */
  void file(AtomModel atom) {
    broadPhase.file(atom);
  }

  /**
   * Before a step's collisions, once for each atom after its servos and its bindings' joints have
   * moved: see {@link BroadPhase#prepare}.
   */
  void prepare(AtomModel atom) {
    broadPhase.prepare(atom);
  }

  /**
   * Collides, steps the world by {@code dt} seconds, and clears the contacts; every atom has been
   * {@link #prepare prepared}.
   */
  void step(double dt) {
    ENGINE.lock();
    try {
      DMisc.dRandSetSeed(seed);
      broadPhase.collide();
      world.quickStep(dt);
      seed = DMisc.dRandGetSeed();
    } finally {
      ENGINE.unlock();
    }
    loadLegs();
    contacts.empty();
  }

  /** The contacts made so far between two atoms: for tests, to tell that atoms met. */
  long atomContacts;

  private final DGeom.DNearCallback nearCallback = this::near;

  private void near(Object data, DGeom o1, DGeom o2) {
    GeomTag t1 = (GeomTag) o1.getData();
    GeomTag t2 = (GeomTag) o2.getData();
    if (t1.atom() != null && t1.atom() == t2.atom()) {
      return;
    }
    DBody b1 = o1.getBody();
    DBody b2 = o2.getBody();
    if (b1 == null && b2 != null) {
      // The engine would swap the bodies of such a contact and turn its normal, but not its first
      // friction direction: the surface motion below is computed for body 1 being o1's.
      near(data, o2, o1);
      return;
    }
    if (b1 != null && b2 != null && OdeHelper.areConnectedExcluding(b1, b2, DContactJoint.class)) {
      return;
    }
    int n = OdeHelper.collide(o1, o2, MAX_CONTACTS, buffer.getGeomBuffer());
    LegModel l1 = t1.kind() == GeomTag.Kind.LEG ? t1.leg() : null;
    LegModel l2 = t2.kind() == GeomTag.Kind.LEG ? t2.leg() : null;
    boolean kinematic1 = l1 instanceof KinematicLeg;
    boolean kinematic2 = l2 instanceof KinematicLeg;
    for (int i = 0; i < n; i++) {
      DContact contact = buffer.get(i);
      contact.surface.mode =
          OdeConstants.dContactApprox1
              | OdeConstants.dContactSoftERP
              | OdeConstants.dContactSoftCFM;
      contact.surface.mu = friction;
      contact.surface.soft_erp = 0.2;
      contact.surface.soft_cfm = 1e-4;
      boolean moving1 = l1 != null && l1.movesOnItsCarrier();
      boolean moving2 = l2 != null && l2.movesOnItsCarrier();
      if (moving1 || moving2) {
        surfaceMotion(contact, l1, l2);
        // A leg that moves where it touches something wakes its atom.
        if (moving1 && b1 != null) {
          b1.enable();
        }
        if (moving2 && b2 != null) {
          b2.enable();
        }
      }
      DContactJoint joint = OdeHelper.createContactJoint(world, contacts, contact);
      joint.attach(b1, b2);
      if (kinematic1 || kinematic2) {
        Load load = nextLoad();
        joint.setFeedback(load.feedback);
        load.set(kinematic1 ? l1 : null, kinematic2 ? l2 : null, contact.geom.pos);
      }
      touch(t1, t2, contact.geom.pos);
      touch(t2, t1, contact.geom.pos);
    }
    if (n > 0 && t1.atom() != null && t2.atom() != null) {
      atomContacts += n;
    }
    if (n > 0 && b1 != null && b2 != null) {
      broadPhase.joined(t1.atom());
      broadPhase.joined(t2.atom());
    }
  }

  /**
   * Gives a contact the velocity of the legs' surfaces relative to their bodies (a kinematic leg
   * turning on its kernel), so the solver makes the surfaces, not the bodies, stick or slide: the
   * contact's friction directions are chosen here, and each "motion" is minus the relative surface
   * velocity along one of them (the engine's sign: body 1 relative to body 2).
   */
  private void surfaceMotion(DContact contact, @Nullable LegModel l1, @Nullable LegModel l2) {
    DVector3C at = contact.geom.pos;
    DVector3C normal = contact.geom.normal;
    double ux = 0;
    double uy = 0;
    double uz = 0;
    if (l1 != null) {
      l1.velocityAt(at, velocity);
      ux += velocity.get0();
      uy += velocity.get1();
      uz += velocity.get2();
    }
    if (l2 != null) {
      l2.velocityAt(at, velocity);
      ux -= velocity.get0();
      uy -= velocity.get1();
      uz -= velocity.get2();
    }
    DVector3 t1 = contact.fdir1;
    OdeMath.dPlaneSpace(normal, t1, t2);
    // The engine takes its second direction as normal × fdir1.
    t2.eqCross(normal, t1);
    contact.surface.mode |=
        OdeConstants.dContactFDir1
            | OdeConstants.dContactMotion1
            | OdeConstants.dContactMotion2
            | OdeConstants.dContactMotionN;
    contact.surface.motion1 = -(ux * t1.get0() + uy * t1.get1() + uz * t1.get2());
    contact.surface.motion2 = -(ux * t2.get0() + uy * t2.get1() + uz * t2.get2());
    contact.surface.motionN = -(ux * normal.get0() + uy * normal.get1() + uz * normal.get2());
  }

  private final DVector3 velocity = new DVector3();
  private final DVector3 t2 = new DVector3();

  /** A contact on a kinematic leg: its force, read after the step, loads the leg. */
  private static final class Load {
    final DJointFeedback feedback = new DJointFeedback();
    final DVector3 at = new DVector3();
    @Nullable LegModel leg1;
    @Nullable LegModel leg2;

    void set(@Nullable LegModel leg1, @Nullable LegModel leg2, DVector3C at) {
      // The engine leaves the feedback of a contact between resting bodies as it was.
      feedback.f1.setZero();
      feedback.f2.setZero();
      feedback.t1.setZero();
      feedback.t2.setZero();
      this.leg1 = leg1;
      this.leg2 = leg2;
      this.at.set(at);
    }
  }

  private final List<Load> loads = new ArrayList<>();
  private int loadCount;

  private Load nextLoad() {
    if (loadCount == loads.size()) {
      loads.add(new Load());
    }
    return loads.get(loadCount++);
  }

  /**
   * Tells kinematic legs the torque their contacts of the last step put on them. The engine's
   * quick-step (ode4j 0.5.3) leaves the force on the joint's first body in {@code f2} and does not
   * fill {@code f1}; a contact pushes its second body with the opposite force.
   */
  private void loadLegs() {
    for (int i = 0; i < loadCount; i++) {
      Load load = loads.get(i);
      if (load.leg1 != null) {
        loadLeg(load.leg1, load.at, load.feedback.f2, 1);
      }
      if (load.leg2 != null) {
        loadLeg(load.leg2, load.at, load.feedback.f2, -1);
      }
    }
    loadCount = 0;
  }

  private static void loadLeg(LegModel leg, DVector3C at, DVector3C f, double sign) {
    DVector3 pivot = leg.pivot();
    double rx = at.get0() - pivot.get0();
    double ry = at.get1() - pivot.get1();
    double rz = at.get2() - pivot.get2();
    leg.addLoad(
        sign * (ry * f.get2() - rz * f.get1()),
        sign * (rz * f.get0() - rx * f.get2()),
        sign * (rx * f.get1() - ry * f.get0()));
  }

  /** Marks a leg's tip as touching {@code other} if the contact is on its far cap. */
  private void touch(GeomTag tag, GeomTag other, DVector3C at) {
    LegModel leg = tag.leg();
    if (tag.kind() != GeomTag.Kind.LEG || leg == null) {
      return;
    }
    boolean world = other.kind() == GeomTag.Kind.WORLD;
    AtomModel atom = leg.atom;
    if (((world ? atom.touchingGrounds : atom.touchingAtoms) & leg.bit) != 0) {
      return;
    }
    DVector3 tip = leg.tip();
    if (tip.distance(at) <= 1.5 * legRadius) {
      atom.contacts |= leg.bit;
      if (world) {
        atom.touchingGrounds |= leg.bit;
      } else {
        atom.touchingAtoms |= leg.bit;
      }
    }
  }

  /** Searches the grid for each step's pairs of atoms: see {@link BroadPhase#searchEveryStep}. */
  void searchEveryStep() {
    broadPhase.searchEveryStep();
  }

  /** Whether the rays asked the grid by rows of cells at the last sensing: for tests. */
  boolean raysQueriedByRows() {
    return broadPhase.grid().queriedByRows();
  }

  void destroy() {
    contacts.destroy();
    broadPhase.destroy();
    world.destroy();
  }
}
