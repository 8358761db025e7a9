package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.TreeMap;
import java.util.function.IntConsumer;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.sim.spi.Pacer;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.jspecify.annotations.Nullable;

/** The simulation: see {@link Simulation} for the order of a control cycle. */
final class SimulationImpl implements Simulation {

  private final Scene scene;
  private final Physics physics;

  /** The threads each pass over the atoms is spread over. */
  private final Lanes lanes;

  private final TreeMap<Integer, BodyView> bodies = new TreeMap<>();
  private final List<AtomModel> atoms = new ArrayList<>();

  /** Each atom's view and controller, at the atom's index: read every cycle without a lookup. */
  private final BodyView[] views;

  private final Controller[] controllers;

  /**
   * Whether each atom, at its index, had a locked, free tip at this cycle's sensing: only those
   * atoms' tips may bind (see {@link #bindLockedTips}).
   */
  private final boolean[] mayBind;

  private final List<Binding> bindings = new ArrayList<>();
  private final MessageBus messages;
  private final TipMatcher tips;
  private final Pacer pacer;
  private final @Nullable TraceWriter trace;
  private final long stepNanos;
  private final int stepsPerCycle;
  private final double dt;
  private final List<SimEvent> events = new ArrayList<>();

  private List<SimEvent> lastEvents = List.of();
  private long cycle;
  private long timeNanos;
  private boolean closed;

  SimulationImpl(SimulationBuilder b) {
    this.scene = b.scene;
    this.stepNanos = b.stepNanos;
    this.stepsPerCycle = (int) (b.periodNanos / b.stepNanos);
    this.dt = b.stepNanos / 1e9;
    this.pacer = b.pacer;
    this.messages = new MessageBus(b.seed, b.messageDelayNanos, b.packetLoss);
    this.physics = new Physics(scene, b.seed, b.threads);
    this.lanes = new Lanes(b.threads, "maam-sim-" + scene.name());
    this.tips = new TipMatcher(scene.params());
    Cone cone = new Cone(scene.params().coneHalfAngle());
    List<Scene.Placement> placements = new ArrayList<>(scene.atoms());
    placements.sort(Comparator.comparingInt(Scene.Placement::id));
    for (Scene.Placement p : placements) {
      AtomModel atom = new AtomModel(physics, atoms.size(), p, scene.params(), cone, b.legDynamics);
      atoms.add(atom);
      physics.add(atom);
      bodies.put(p.id(), new BodyView(this, atom));
    }
    emptied = new boolean[atoms.size()];
    mayBind = new boolean[atoms.size()];
    views = new BodyView[atoms.size()];
    controllers = new Controller[atoms.size()];
    for (AtomModel atom : atoms) {
      views[atom.index] = bodies.get(atom.id);
      Controller c = b.controllerById.get(atom.id);
      controllers[atom.index] = c != null ? c : b.controllers.apply(atom.id);
    }
    for (Scene.Bond bond : scene.bonds()) {
      LegModel a = bodies.get(bond.atomA()).model.leg(bond.legA());
      LegModel c = bodies.get(bond.atomB()).model.leg(bond.legB());
      if (!tips.inTolerance(a, c)) {
        throw new IllegalArgumentException(
            "scene '"
                + scene.name()
                + "': bond "
                + bond
                + " joins tips "
                + a.tip().distance(c.tip())
                + " m apart or misaligned; expected within "
                + scene.params().bindDistance()
                + " m and "
                + Math.toDegrees(scene.params().bindAlignment())
                + " degrees");
      }
      a.locked = true;
      c.locked = true;
      bindings.add(new Binding(physics, a, c));
    }
    this.trace = b.trace == null ? null : new TraceWriter(b.trace);
    if (trace != null) {
      trace.header(scene, b.seed, b.stepNanos, b.periodNanos, atomIds(), b.traceAttributes);
    }
  }

  @Override
  public Scene scene() {
    return scene;
  }

  @Override
  public List<Integer> atomIds() {
    return List.copyOf(bodies.keySet());
  }

  @Override
  public AtomSensors sensors(int id) {
    return view(id).sensors;
  }

  /** Atom {@code id} in the physics' terms. */
  BodyView view(int id) {
    BodyView view = bodies.get(id);
    if (view == null) {
      throw new IllegalArgumentException(
          "no atom " + id + " in scene '" + scene.name() + "'; atoms: " + bodies.keySet());
    }
    return view;
  }

  @Override
  public Body body(int id) {
    return view(id).body;
  }

  @Override
  public void setController(int id, Controller controller) {
    controllers[view(id).model.index] = java.util.Objects.requireNonNull(controller, "controller");
  }

  @Override
  public long cycle() {
    return cycle;
  }

  @Override
  public long timeNanos() {
    return timeNanos;
  }

  @Override
  public List<SimEvent> lastEvents() {
    return lastEvents;
  }

  @Override
  public void runCycle() {
    if (closed) {
      throw new IllegalStateException("simulation of scene '" + scene.name() + "' is closed");
    }
    long start = timeNanos;
    // Sensing empties the inboxes too.
    senseAll();
    messages.deliver(start);
    bindLockedTips();
    runControllers();
    boolean servoed = false;
    for (int i = 0; i < stepsPerCycle; i++) {
      servoed = physicsStep(servoed, i == stepsPerCycle - 1);
    }
    // The last step's drain took back the pushes.
    if (trace != null) {
      List<BodyView> readings = new ArrayList<>(atoms.size());
      for (AtomModel atom : atoms) {
        readings.add(views[atom.index]);
      }
      trace.cycle(cycle, start, readings, events);
    }
    lastEvents = List.copyOf(events);
    events.clear();
    cycle++;
    pacer.pace(timeNanos);
  }

  /**
   * Every working atom's controller, in atom order; if they are all {@link Controller#confined
   * confined} and there are lanes, on the lanes at once (decision 0077). A confined controller
   * reads its own atom's readings and inbox, and writes its own atom's legs; the binds, unbinds and
   * sends it makes, which write what other atoms read, wait in its view until the pass is over, and
   * are carried out then in atom order: in the order one thread would carry them out, since no
   * controller reads, during the pass, what they write.
   */
  private void runControllers() {
    if (lanes.lanes() == 1 || !allConfined()) {
      for (int i = 0; i < atoms.size(); i++) {
        control(i);
      }
      return;
    }
    controllingOnLanes = true;
    try {
      lanes.forEach(atoms.size(), controlPass);
    } catch (RuntimeException | Error e) {
      for (BodyView view : views) {
        view.dropDeferred();
      }
      throw e;
    } finally {
      controllingOnLanes = false;
    }
    for (BodyView view : views) {
      view.runDeferred();
    }
  }

  private void control(int i) {
    if (!atoms.get(i).failed) {
      controllers[i].onCycle(views[i].body, cycle);
    }
  }

  private final IntConsumer controlPass = this::control;

  /** Whether every atom's controller is {@link Controller#confined confined}. */
  private boolean allConfined() {
    for (Controller c : controllers) {
      if (!c.isConfined()) {
        return false;
      }
    }
    return true;
  }

  /**
   * Whether the controllers are running on the lanes: then binds, unbinds and sends wait (see
   * {@link #runControllers}). Written before and after the pass, read in it.
   */
  private boolean controllingOnLanes;

  boolean controllingOnLanes() {
    return controllingOnLanes;
  }

  /**
   * One physics step. Each pass over the atoms does all it can for an atom at once (with a thousand
   * atoms, each pass reads them from memory afresh), on the {@link Lanes}; what must go in order
   * (bindings, contacts, the solver, events) goes on this thread between passes.
   *
   * <p>Unless {@code last}, a step without bindings runs the next step's servos in the same pass as
   * its own drain, atom by atom, saving a pass (decision 0073; {@code servoed} says the last step
   * did, and the result whether this one did): an atom's drain and servos read and write that atom
   * alone, and between the two passes there would only be the step's events, which read no atom.
   * Bindings are made and released only between cycles, but they break between the passes, and a
   * bound leg's servo reads the other atom: with any binding the passes stay apart.
   */
  private boolean physicsStep(boolean servoed, boolean last) {
    // Bindings re-fix their joints after both legs' servos and before collisions.
    following = !bindings.isEmpty();
    if (!servoed) {
      lanes.forEach(atoms.size(), servoPass);
    }
    if (following) {
      for (Binding binding : bindings) {
        binding.follow();
      }
      lanes.forEach(atoms.size(), preparePass);
    }
    physics.step(dt);
    for (Binding binding : bindings) {
      binding.loadLegs();
    }
    timeNanos += stepNanos;
    // With no binding now, none breaks after the pass: the next step follows none either.
    boolean servoNext = fusePasses && !last && bindings.isEmpty();
    lanes.forEach(atoms.size(), servoNext ? drainServoPass : last ? drainLastPass : drainPass);
    for (int i = 0; i < atoms.size(); i++) {
      if (emptied[i]) {
        events.add(new SimEvent.BatteryEmpty(timeNanos, atoms.get(i).id));
      }
    }
    for (int i = 0; i < bindings.size(); i++) {
      Binding binding = bindings.get(i);
      double force = binding.force();
      if (force > scene.params().bindStrength()) {
        binding.release();
        binding.a.locked = false;
        binding.b.locked = false;
        bindings.remove(i--);
        events.add(
            new SimEvent.BindingBroke(
                timeNanos,
                binding.a.atom.id,
                binding.a.leg,
                binding.b.atom.id,
                binding.b.leg,
                force));
      }
    }
    return servoNext;
  }

  private boolean following;
  private boolean[] emptied = new boolean[0];
  private final IntConsumer servoPass = this::servo;
  private final IntConsumer preparePass = this::prepare;

  /**
   * Whether a step without bindings runs the next step's servos in its own drain pass (decision
   * 0073). Off only in the test that holds both ways to the same run.
   */
  private boolean fusePasses = true;

  /** Every step's drain and servos in passes of their own, as with bindings: for tests. */
  void separatePasses() {
    fusePasses = false;
  }

  /** Every leg's servo worked out at every step, none skipped as resting: for tests. */
  void neverRest() {
    for (AtomModel atom : atoms) {
      atom.mayRest = false;
    }
  }

  /** The contacts made so far between two atoms: for tests. */
  long atomContacts() {
    return physics.atomContacts;
  }

  /** Each step's pairs of atoms from a search of the grid (decision 0076): for tests. */
  void searchEveryStep() {
    physics.searchEveryStep();
  }

  /** Whether the rays asked the grid by rows of cells at this cycle's sensing: for tests. */
  boolean raysQueriedByRows() {
    return physics.raysQueriedByRows();
  }

  private final IntConsumer drainPass = this::drain;
  private final IntConsumer drainServoPass = this::drainServo;
  private final IntConsumer drainLastPass = this::drainLast;
  private final IntConsumer readyPass = this::ready;
  private final Lanes.LaneWork castSensePass = this::castAndSense;

  /** Atom {@code i}'s push and servos, and (unless bindings follow first) its preparation. */
  private void servo(int i) {
    AtomModel atom = atoms.get(i);
    if (atom.pushX != 0 || atom.pushY != 0 || atom.pushZ != 0) {
      atom.kernel.enable();
      atom.kernel.addForce(atom.pushX, atom.pushY, atom.pushZ);
    }
    boolean on = atom.motorsOn();
    LegModel[] legs = atom.legs;
    int awake = ~atom.resting;
    for (int l = 0; l < legs.length; l++) {
      // A resting leg's servo would write what is there (see AtomModel.resting).
      if ((awake & 1 << l) != 0) {
        legs[l].servo(on, dt);
      }
    }
    if (!following) {
      physics.prepare(atom);
    }
  }

  private void prepare(int i) {
    physics.prepare(atoms.get(i));
  }

  /** After the engine's step: atom {@code i}'s parts, legs and battery. */
  private void drain(int i) {
    AtomModel atom = atoms.get(i);
    atom.stepped();
    emptied[i] = atom.drain(dt);
  }

  /**
   * The last step's drain of atom {@code i}: the cycle's pushes on it end with its servos. Its rays
   * that stay in place are placed now, while the atom is at hand, not at the next sensing, which
   * with a thousand atoms reads it from memory afresh: nothing moves an atom between the two, and
   * what moves a leg or a kernel takes its rays out of place.
   */
  private void drainLast(int i) {
    drain(i);
    AtomModel atom = atoms.get(i);
    atom.pushX = 0;
    atom.pushY = 0;
    atom.pushZ = 0;
    if (!atom.failed) {
      for (LegModel leg : atom.legs) {
        if (!leg.rayInPlace && leg.keepsItsRay() && !leg.failed && leg.binding == null) {
          leg.placeRay();
        }
      }
    }
  }

  /** Atom {@code i}'s {@link #drain}, then its {@link #servo} for the next step. */
  private void drainServo(int i) {
    drain(i);
    servo(i);
  }

  /**
   * The sensing pass, over the atoms twice, not four times (decision 0073): each atom is filed for
   * the rays, then, once every atom is filed, aimed, cast and read at once (decision 0080): aiming
   * an atom writes its own rays alone, which only its own casting reads. On one lane the parts a
   * ray needs are placed as it needs them. On more, each lane casts its atoms' rays at once with
   * the others' (decision 0075): the first pass also readies each atom's parts, so that casting
   * reads what no lane writes, and the grid is filed on this thread between the passes. Each lane
   * casts exactly what one lane would, so the readings are the same on any number of lanes.
   */
  private void senseAll() {
    if (lanes.lanes() == 1) {
      for (int i = 0; i < atoms.size(); i++) {
        physics.file(atoms.get(i));
      }
      physics.fileForRays();
      for (int i = 0; i < atoms.size(); i++) {
        castAndSense(0, i);
      }
      return;
    }
    lanes.forEach(atoms.size(), readyPass);
    physics.fileForRays();
    lanes.forEach(atoms.size(), castSensePass);
  }

  /**
   * Atom {@code i} filed and readied for rays cast on several lanes: it writes atom {@code i}'s
   * legs, parts and box alone.
   */
  private void ready(int i) {
    AtomModel atom = atoms.get(i);
    physics.file(atom);
    physics.readyForRays(atom);
  }

  /**
   * Atom {@code i}'s rays aimed and cast on {@code lane}, then its sensors read: aiming and casting
   * write only its own legs' rays and proximities, and reading writes only its own legs, view and
   * inbox, none of which another lane's rays read (they read the engine's geometries and bodies,
   * the boxes and the grid, and the legs' poses, which readying left worked out).
   */
  private void castAndSense(int lane, int i) {
    aim(i);
    physics.castRays(lane, atoms.get(i));
    sense(i);
  }

  /** Aims atom {@code i}'s proximity rays, but those of failed or bound legs. */
  private void aim(int i) {
    AtomModel atom = atoms.get(i);
    int aimed = 0;
    for (LegModel leg : atom.legs) {
      if (atom.failed || leg.failed) {
        continue;
      }
      if (leg.binding != null) {
        leg.proximity = 0;
      } else {
        leg.aimRay();
        aimed |= leg.bit;
      }
    }
    atom.aimed = aimed;
  }

  /**
   * Reads atom {@code i}'s sensors, starts its tips' contacts of the next period afresh, empties
   * its inbox for the messages of the cycle, and notes whether it has a tip that may {@link
   * #mayBind bind}.
   */
  private void sense(int i) {
    AtomModel atom = atoms.get(i);
    atom.inbox.clear();
    BodyView view = views[i];
    view.sensors = sense(atom, view.joints);
    atom.contacts = 0;
    boolean locked = false;
    for (LegModel leg : atom.legs) {
      locked |= TipMatcher.lockedAndFree(leg);
    }
    mayBind[i] = locked && !atom.failed;
  }

  /**
   * What {@code atom} senses now; its legs' joint angles go to {@code joints} as the physics has
   * them, for the trace, and leave as {@link LegSensors#angles()} through {@link JointAngles}.
   */
  AtomSensors sense(AtomModel atom, double[] joints) {
    List<LegSensors> legs = new ArrayList<>(6);
    for (Leg l : Leg.values()) {
      LegModel leg = atom.leg(l);
      int j = 2 * l.ordinal();
      if (atom.failed || leg.failed) {
        joints[j] = 0;
        joints[j + 1] = 0;
        legs.add(
            new LegSensors(
                l,
                LegAngles.AXIS,
                0,
                0,
                false,
                false,
                OptionalInt.empty(),
                Optional.empty(),
                0,
                true));
      } else {
        Binding b = leg.binding;
        double a1 = leg.angle1();
        double a2 = leg.angle2();
        joints[j] = a1;
        joints[j + 1] = a2;
        legs.add(
            new LegSensors(
                l,
                leg.angles(a1, a2),
                leg.torque1,
                leg.torque2,
                leg.contact(),
                leg.locked,
                b == null ? OptionalInt.empty() : OptionalInt.of(b.other(leg).atom.id),
                b == null ? Optional.empty() : Optional.of(b.other(leg).leg),
                leg.proximity,
                false));
      }
    }
    if (atom.failed) {
      return new AtomSensors(
          atom.id, timeNanos, atom.position(), atom.orientation(), 0, 0, true, legs);
    }
    return new AtomSensors(
        atom.id,
        timeNanos,
        atom.position(),
        atom.orientation(),
        atom.tilt(),
        atom.energy,
        false,
        legs);
  }

  /**
   * Binds the pairs of locked, free tips in tolerance, among the atoms that had such a tip at this
   * cycle's sensing ({@link #mayBind}, worked out while each atom was read): nothing locks or frees
   * a tip between the sensing and here, so these are the atoms {@link TipMatcher#pairs} would take
   * from the whole list, in the same order, and a cycle with none goes over no atom.
   */
  private void bindLockedTips() {
    List<AtomModel> locked = new ArrayList<>();
    for (int i = 0; i < mayBind.length; i++) {
      if (mayBind[i]) {
        locked.add(atoms.get(i));
      }
    }
    if (locked.isEmpty()) {
      return;
    }
    for (LegModel[] pair : tips.pairs(locked)) {
      bindings.add(new Binding(physics, pair[0], pair[1]));
      events.add(
          new SimEvent.Bound(
              timeNanos, pair[0].atom.id, pair[0].leg, pair[1].atom.id, pair[1].leg));
    }
  }

  void unbind(LegModel leg) {
    leg.locked = false;
    Binding b = leg.binding;
    if (b != null) {
      LegModel other = b.other(leg);
      b.release();
      bindings.remove(b);
      events.add(new SimEvent.Unbound(timeNanos, leg.atom.id, leg.leg, other.atom.id, other.leg));
    }
  }

  /** Whether a message sent from {@code leg} now goes: its atom and it work, and it is bound. */
  static boolean canSend(LegModel leg) {
    return !leg.atom.failed && !leg.failed && leg.binding != null;
  }

  boolean send(LegModel leg, String payload) {
    if (!canSend(leg)) {
      return false;
    }
    LegModel to = java.util.Objects.requireNonNull(leg.binding).other(leg);
    ReceivedMessage m = new ReceivedMessage(leg.atom.id, leg.leg, to.leg, timeNanos, payload);
    if (!messages.send(timeNanos, to.atom, m)) {
      events.add(new SimEvent.MessageLost(timeNanos, leg.atom.id, leg.leg));
    }
    return true;
  }

  @Override
  public void push(int id, Vec3 force) {
    AtomModel atom = view(id).model;
    atom.pushX += force.x();
    atom.pushY += force.y();
    atom.pushZ += force.z();
  }

  @Override
  public void failAtom(int id) {
    AtomModel atom = view(id).model;
    if (!atom.failed) {
      atom.fail();
      atom.inbox.clear();
      events.add(new SimEvent.AtomFailed(timeNanos, id));
    }
  }

  @Override
  public void failLeg(int id, Leg leg) {
    LegModel model = view(id).model.leg(leg);
    if (!model.failed) {
      model.fail();
      events.add(new SimEvent.LegFailed(timeNanos, id, leg));
    }
  }

  @Override
  public void setPacketLoss(double probability) {
    messages.setLoss(probability);
  }

  @Override
  public void note(int id, String text) {
    view(id);
    events.add(new SimEvent.Note(timeNanos, id, text));
  }

  @Override
  public void close() {
    if (closed) {
      return;
    }
    closed = true;
    lanes.close();
    if (trace != null) {
      trace.flush();
    }
    physics.destroy();
  }
}
