package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import org.jspecify.annotations.Nullable;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DAABBC;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DContact;
import org.ode4j.ode.DContactBuffer;
import org.ode4j.ode.DContactJoint;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DJoint.DJointFeedback;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DMisc;
import org.ode4j.ode.DRay;
import org.ode4j.ode.DRotation;
import org.ode4j.ode.DSpace;
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

  private static final int PIPE_STAVES = 16;

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

  /** The ground, the plane z = 0; like the obstacles, in no space (see {@link #collide()}). */
  private final DGeom ground;

  private final List<DGeom> obstacles = new ArrayList<>();

  /** The atoms, in id order, and the spaces of their parts. */
  private final List<AtomModel> atoms = new ArrayList<>();

  private final List<DSpace> parts = new ArrayList<>();
  private final AtomGrid grid = new AtomGrid();
  private final DJointGroup contacts = OdeHelper.createJointGroup();
  private final DContactBuffer buffer = new DContactBuffer(MAX_CONTACTS);
  private final double friction;
  private final double legRadius;
  private long seed;

  Physics(Scene scene, long seed) {
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
    ground = OdeHelper.createPlane(null, 0, 0, 1, 0);
    ground.setData(GeomTag.WORLD);
    for (Obstacle o : scene.obstacles()) {
      switch (o) {
        case Obstacle.Box b -> box(b.center(), b.size(), new DMatrix3().setIdentity());
        case Obstacle.Pipe p -> pipe(p);
      }
    }
  }

  private void box(Vec3 center, Vec3 size, DMatrix3 rotation) {
    DBox box = OdeHelper.createBox(null, size.x(), size.y(), size.z());
    box.setPosition(center.x(), center.y(), center.z());
    box.setRotation(rotation);
    box.setData(GeomTag.WORLD);
    obstacles.add(box);
  }

  /** A pipe of flat staves around its axis: each stave a thin box, tangent to the inner radius. */
  private void pipe(Obstacle.Pipe p) {
    double mid = p.innerRadius() + p.wall() / 2;
    double width = 2 * (p.innerRadius() + p.wall()) * Math.tan(Math.PI / PIPE_STAVES) * 1.05;
    for (int i = 0; i < PIPE_STAVES; i++) {
      double phi = 2 * Math.PI * i / PIPE_STAVES;
      double u = Math.cos(phi) * mid;
      double v = Math.sin(phi) * mid;
      Vec3 c = p.center();
      DMatrix3 r = new DMatrix3();
      // A box with length along the pipe's axis, thickness along the radius, width tangent.
      switch (p.axis()) {
        case 'x' -> {
          DRotation.dRFromAxisAndAngle(r, 1, 0, 0, phi);
          box(new Vec3(c.x(), c.y() + u, c.z() + v), new Vec3(p.length(), p.wall(), width), r);
        }
        case 'y' -> {
          DRotation.dRFromAxisAndAngle(r, 0, 1, 0, -phi);
          box(new Vec3(c.x() + v, c.y(), c.z() + u), new Vec3(width, p.length(), p.wall()), r);
        }
        default -> {
          DRotation.dRFromAxisAndAngle(r, 0, 0, 1, phi);
          box(new Vec3(c.x() + u, c.y() + v, c.z()), new Vec3(p.wall(), width, p.length()), r);
        }
      }
    }
  }

  /** Adds an atom, whose parts are in the space {@code atom.parts}; atoms are added in id order. */
  void add(AtomModel atom) {
    atoms.add(atom);
    parts.add(atom.parts);
  }

  /**
   * Casts the proximity rays of {@code legs} (aimed) against everything but their own atoms: the
   * sensing pass at the start of a control cycle.
   */
  void castRays(List<LegModel> legs) {
    ENGINE.lock();
    try {
      cleanParts();
      DAABBC groundBox = ground.getAABB();
      for (LegModel leg : legs) {
        DRay ray = leg.ray;
        DAABBC box = ray.getAABB();
        if (overlap(box, groundBox)) {
          near(null, ray, ground);
        }
        for (DGeom obstacle : obstacles) {
          if (overlap(box, obstacle.getAABB())) {
            near(null, ray, obstacle);
          }
        }
        AtomModel own = leg.atom;
        grid.forEachOverlapping(
            box,
            a -> {
              if (atoms.get(a) != own) {
                near(null, ray, parts.get(a));
              }
            });
      }
    } finally {
      ENGINE.unlock();
    }
  }

  /** Collides, steps the world by {@code dt} seconds, and clears the contacts. */
  void step(double dt) {
    ENGINE.lock();
    try {
      DMisc.dRandSetSeed(seed);
      collide();
      world.quickStep(dt);
      seed = DMisc.dRandGetSeed();
    } finally {
      ENGINE.unlock();
    }
    loadLegs();
    contacts.empty();
  }

  /**
   * Brings the parts' bounding boxes up to date and files the atoms in the grid. Every atom's space
   * is cleaned every time, as the engine's hash space did with its entries: the engine keeps a
   * space's parts in the order they last moved in since it was cleaned, and contacts are made in
   * that order.
   */
  private void cleanParts() {
    for (DSpace s : parts) {
      s.cleanGeoms();
    }
    grid.rebuild(parts);
  }

  /**
   * Makes this step's contacts: between atoms whose boxes overlap (found with the {@link
   * AtomGrid}), between atoms and obstacles, then between atoms and the ground. Each body's
   * contacts are made in the order the engine's hash space made them (contacts with other atoms and
   * obstacles first, then the ground's; each atom's parts in its space's order), except that pairs
   * of atoms and of an atom and several obstacles come in an order of their own: the solver visits
   * a body's contacts in the order they were made, so an atom that touches only the ground (and one
   * obstacle) moves bit for bit as it did (decision 0062).
   */
  private void collide() {
    cleanParts();
    grid.forEachPair(pairNear);
    for (DSpace s : parts) {
      DAABBC box = s.getAABB();
      for (DGeom obstacle : obstacles) {
        if (overlap(box, obstacle.getAABB())) {
          near(null, s, obstacle);
        }
      }
    }
    DAABBC groundBox = ground.getAABB();
    for (DSpace s : parts) {
      if (overlap(s.getAABB(), groundBox)) {
        near(null, s, ground);
      }
    }
  }

  private final AtomGrid.PairVisitor pairNear = (a, b) -> near(null, parts.get(a), parts.get(b));

  /** The engine's test: boxes that touch overlap. */
  private static boolean overlap(DAABBC a, DAABBC b) {
    return a.getMin0() <= b.getMax0()
        && b.getMin0() <= a.getMax0()
        && a.getMin1() <= b.getMax1()
        && b.getMin1() <= a.getMax1()
        && a.getMin2() <= b.getMax2()
        && b.getMin2() <= a.getMax2();
  }

  private final DGeom.DNearCallback nearCallback = this::near;

  private void near(Object data, DGeom o1, DGeom o2) {
    GeomTag t1 = (GeomTag) o1.getData();
    GeomTag t2 = (GeomTag) o2.getData();
    boolean rays = t1.kind() == GeomTag.Kind.RAY || t2.kind() == GeomTag.Kind.RAY;
    if (t1.kind() == GeomTag.Kind.ATOM || t2.kind() == GeomTag.Kind.ATOM) {
      // An atom's space near something else: look inside.
      if (!rays && still(t1) && still(t2)) {
        // Nothing moves: the contacts would be those of the last step, which the solver ignores
        // between resting bodies; the tips keep the contact state they had.
        return;
      }
      if (t1.atom() != t2.atom()) {
        OdeHelper.spaceCollide2(o1, o2, data, nearCallback);
      }
      return;
    }
    if (rays) {
      ray(t1, o1, t2, o2);
      return;
    }
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
      touch(t1, contact.geom.pos);
      touch(t2, contact.geom.pos);
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

  /** A resting atom or the world, for collisions. */
  private static boolean still(GeomTag tag) {
    AtomModel atom = tag.atom();
    return tag.kind() == GeomTag.Kind.WORLD || (atom != null && atom.still);
  }

  /** Marks a leg's tip as touching if the contact is on its far cap. */
  private void touch(GeomTag tag, DVector3C at) {
    LegModel leg = tag.leg();
    if (tag.kind() != GeomTag.Kind.LEG || leg == null || leg.touching) {
      return;
    }
    DVector3 tip = leg.tip();
    if (tip.distance(at) <= 1.5 * legRadius) {
      leg.contact = true;
      leg.touching = true;
    }
  }

  private void ray(GeomTag t1, DGeom o1, GeomTag t2, DGeom o2) {
    if (t1.kind() == GeomTag.Kind.RAY && t2.kind() == GeomTag.Kind.RAY) {
      return;
    }
    if (t1.atom() != null && t1.atom() == t2.atom()) {
      return;
    }
    LegModel leg = t1.kind() == GeomTag.Kind.RAY ? t1.leg() : t2.leg();
    if (leg == null) {
      return;
    }
    int n = OdeHelper.collide(o1, o2, 1, buffer.getGeomBuffer());
    if (n > 0) {
      leg.proximity = Math.min(leg.proximity, buffer.get(0).geom.depth);
    }
  }

  void destroy() {
    contacts.destroy();
    for (AtomModel atom : atoms) {
      atom.parts.destroy();
      for (LegModel leg : atom.legs.values()) {
        leg.ray.destroy();
      }
    }
    for (DGeom obstacle : obstacles) {
      obstacle.destroy();
    }
    ground.destroy();
    world.destroy();
  }
}
