package org.armgals.maam.sim;

import java.util.concurrent.locks.ReentrantLock;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DContact;
import org.ode4j.ode.DContactBuffer;
import org.ode4j.ode.DContactJoint;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DMisc;
import org.ode4j.ode.DRotation;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeConstants;
import org.ode4j.ode.OdeHelper;
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

  private static final Logger LOG = LoggerFactory.getLogger(Physics.class);

  static {
    OdeHelper.initODE2(0);
    // The engine's informational messages (e.g. "zero length vector" while a universal joint's
    // first axis is set before its second) are debug output, not news for users.
    ErrorHdl.dSetMessageHandler(
        (num, format, args) -> LOG.debug("ode4j message {}: {}", num, format));
  }

  final DWorld world;
  final DSpace space;
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
    space = OdeHelper.createHashSpace();
    OdeHelper.createPlane(space, 0, 0, 1, 0).setData(GeomTag.WORLD);
    for (Obstacle o : scene.obstacles()) {
      switch (o) {
        case Obstacle.Box b -> box(b.center(), b.size(), new DMatrix3().setIdentity());
        case Obstacle.Pipe p -> pipe(p);
      }
    }
  }

  private void box(Vec3 center, Vec3 size, DMatrix3 rotation) {
    DBox box = OdeHelper.createBox(space, size.x(), size.y(), size.z());
    box.setPosition(center.x(), center.y(), center.z());
    box.setRotation(rotation);
    box.setData(GeomTag.WORLD);
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

  private boolean raysOnly;

  /**
   * Casts the enabled proximity rays against everything else, and nothing else: the sensing pass at
   * the start of a control cycle.
   */
  void castRays() {
    ENGINE.lock();
    raysOnly = true;
    try {
      space.collide(null, this::near);
    } finally {
      raysOnly = false;
      ENGINE.unlock();
    }
  }

  /** Collides, steps the world by {@code dt} seconds, and clears the contacts. */
  void step(double dt) {
    ENGINE.lock();
    try {
      DMisc.dRandSetSeed(seed);
      space.collide(null, this::near);
      world.quickStep(dt);
      seed = DMisc.dRandGetSeed();
    } finally {
      ENGINE.unlock();
    }
    contacts.empty();
  }

  private void near(Object data, DGeom o1, DGeom o2) {
    GeomTag t1 = (GeomTag) o1.getData();
    GeomTag t2 = (GeomTag) o2.getData();
    if (t1.kind() == GeomTag.Kind.RAY || t2.kind() == GeomTag.Kind.RAY) {
      ray(t1, o1, t2, o2);
      return;
    }
    if (raysOnly) {
      return;
    }
    if (t1.atom() != null && t1.atom() == t2.atom()) {
      return;
    }
    DBody b1 = o1.getBody();
    DBody b2 = o2.getBody();
    if (b1 != null && b2 != null && OdeHelper.areConnectedExcluding(b1, b2, DContactJoint.class)) {
      return;
    }
    int n = OdeHelper.collide(o1, o2, MAX_CONTACTS, buffer.getGeomBuffer());
    for (int i = 0; i < n; i++) {
      DContact contact = buffer.get(i);
      contact.surface.mode =
          OdeConstants.dContactApprox1
              | OdeConstants.dContactSoftERP
              | OdeConstants.dContactSoftCFM;
      contact.surface.mu = friction;
      contact.surface.soft_erp = 0.2;
      contact.surface.soft_cfm = 1e-4;
      OdeHelper.createContactJoint(world, contacts, contact).attach(b1, b2);
      touch(t1, contact.geom.pos);
      touch(t2, contact.geom.pos);
    }
  }

  /** Marks a leg's tip as touching if the contact is on its far cap. */
  private void touch(GeomTag tag, DVector3C at) {
    LegModel leg = tag.leg();
    if (tag.kind() != GeomTag.Kind.LEG || leg == null || leg.contact) {
      return;
    }
    DVector3 tip = leg.tip();
    if (tip.distance(at) <= 1.5 * legRadius) {
      leg.contact = true;
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
    space.destroy();
    world.destroy();
  }
}
