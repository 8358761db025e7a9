package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.TreeMap;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.Threshold;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Actuator;
import org.armgals.maam.BehaviorModule;
import org.armgals.maam.Emission;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.Signal;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.representation.p.PState;

/**
 * The robot of one atom of {@link Distributed}'s chain, in the atom's own runtime: one schema,
 * {@code crawl}, where {@code clock} (a perceptor of the world's time) feeds {@value #GAIT} (a
 * reactor placing the atom in the chain's wave, {@link DistributedGait}), which feeds {@code legs}
 * (an actuator driving the two lower legs). The phase comes from the world's time in the readings,
 * not from the robot's own clock: the robot answers each reading with the same commands however
 * late it comes, so the world's run does not depend on when the atom's island ticks. Its {@code
 * receive} schema feeds the body the readings the world sent its entity; its {@code report} schema
 * sends the world the commands of the cycle before (the body makes them when a cycle ends), with
 * the number of the last notification the robot had sent its meta by then.
 *
 * <p>It shows its meta level ({@link #observe()}) the fraction of a full battery its readings say
 * is left ({@value #FRACTION}) and the amplitude of its stroke ({@value #SWING}); its kernel
 * watches {@link #LOW_BATTERY} on the fraction. Its kind ({@link #kind}, the same in the atom's JVM
 * and in the meta's) has one module in its catalog, the {@value #GAIT} with another swing from a
 * world time on ({@link #FROM}): what its meta asks for with {@code changeModule}.
 */
final class DistributedCrawler extends AbstractRobot {
  static final Port<Phase> PHASE = Port.of("phase", Phase.class);
  static final Port<Stride> STRIDE = Port.of("stride", Stride.class);

  /** The gait module's name, and its catalog entry's. */
  static final String GAIT = "gait";

  /** The observed fraction of a full battery left, in [0, 1]. */
  static final String FRACTION = "fraction";

  /** The observed amplitude of the stroke, rad; the gait's parameter in a request. */
  static final String SWING = "swing";

  /** The gait's parameter: the world time, in ns, from whose readings on the new swing applies. */
  static final String FROM = "fromNanos";

  /**
   * The threshold meta-event its kernel watches on {@value #FRACTION}: below half a battery; above
   * again over 60%.
   */
  static final Threshold LOW_BATTERY = new Threshold("low-battery", FRACTION, 0.5, 0.6);

  /** Where the atom is in its stroke, in [0, 1), at the world time {@code timeNanos}. */
  record Phase(double value, long timeNanos) implements Signal {}

  /** Where the two lower legs should point, swinging {@code swing} rad from their axes. */
  record Stride(LegAngles minusZ, LegAngles minusY, double swing) implements Signal {}

  private final DistributedRemoteBody remote;
  private final double capacity;
  private final LongSupplier notified;
  private final Consumer<Object> toWorld;

  /**
   * @param capacity the energy of a full battery, J
   * @param notified the number of the last notification the robot's entity sent its meta (0: none)
   * @param toWorld where the robot's messages to the world go (its commands), on the robot's thread
   */
  DistributedCrawler(
      DistributedRemoteBody body,
      int index,
      int count,
      double capacity,
      LongSupplier notified,
      Consumer<Object> toWorld) {
    super(
        robotName(body.atom()),
        body,
        () -> Math.max(0, body.read(DistributedRemoteBody.WORLD_TIME)));
    if (!(capacity > 0)) {
      throw new IllegalArgumentException("battery capacity " + capacity + " J: expected > 0");
    }
    this.remote = body;
    this.capacity = capacity;
    this.notified = requireNonNull(notified, "notified");
    this.toWorld = requireNonNull(toWorld, "toWorld");
    WorldClock clock = new WorldClock("clock", index, count);
    Gait gait = new Gait(GAIT, DistributedGait.SWING);
    LegDrive legs = new LegDrive("legs");
    addSchema(Schema.builder("receive").add(new Inlink()).build());
    addSchema(
        Schema.builder("crawl")
            .add(clock)
            .add(gait)
            .add(legs)
            .wire(clock, PHASE, gait, PHASE)
            .wire(gait, STRIDE, legs, STRIDE)
            .build());
    addSchema(Schema.builder("report").add(new Outlink()).build());
  }

  /** The name of atom {@code atom}'s robot, its kernel entity's: {@code crawler-a<atom>}. */
  static String robotName(int atom) {
    return "crawler-a" + atom;
  }

  /**
   * The kind of the crawlers, {@code DistributedCrawler}: they observe {@value #FRACTION} and
   * {@value #SWING}, and its catalog has the {@value #GAIT} with a {@value #SWING} (rad) from a
   * world time on ({@value #FROM}, ns). Defined the same way in an atom's JVM and in its meta's.
   */
  static StructuralMeta<PState> kind(Kernel kernel) {
    return RobotKind.builder("DistributedCrawler", DistributedCrawler.class)
        .observing(Map.of(FRACTION, 1.0, SWING, DistributedGait.SWING))
        .module(GAIT, (robot, p) -> robot.gait().from(p.whole(FROM), p.number(SWING)))
        .define(kernel);
  }

  /** The gait it runs now. */
  Gait gait() {
    for (BehaviorModule m : schedule().modules()) {
      if (m instanceof Gait g) {
        return g;
      }
    }
    throw new IllegalStateException("robot " + name() + " runs no " + GAIT);
  }

  /**
   * What the robot shows its meta level: the robot's own, the fraction of a full battery left (1
   * before the first readings), and the swing of its last stride (the gait's first before any).
   */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    long time = remote.read(DistributedRemoteBody.WORLD_TIME);
    double fraction = time < 0 ? 1.0 : remote.read(Atom.BATTERY) / capacity;
    double swing = DistributedGait.SWING;
    for (Emission e : emissions()) {
      if (e.signal() instanceof Stride s) {
        swing = s.swing();
      }
    }
    m.put(FRACTION, fraction);
    m.put(SWING, swing);
    return m;
  }

  /**
   * Feeds the body the readings the world sent the robot's entity, taken at this release: the first
   * module of each cycle.
   */
  private final class Inlink implements Perceptor {
    @Override
    public String name() {
      return "inlink";
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of();
    }

    @Override
    public void perceive(Body body, Outputs out) {
      for (Object input : received()) {
        if (input instanceof DistributedWire.Readings readings) {
          remote.feed(readings);
        }
      }
    }
  }

  /**
   * Sends the world the commands the last cycle made, if they answer new readings: the last module.
   * The kernel notified that cycle when it ended, so the commands carry the number of every
   * notification of the readings they answer.
   */
  private final class Outlink implements Actuator {
    @Override
    public String name() {
      return "outlink";
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of();
    }

    @Override
    public void act(Inputs in, Body body) {
      DistributedWire.Commands commands = remote.takeCommands(notified.getAsLong());
      if (commands != null) {
        toWorld.accept(commands);
      }
    }
  }

  /** The atom's phase from the world's time; nothing before the first readings. */
  record WorldClock(String name, int index, int count) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(PHASE);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      long nanos = body.read(DistributedRemoteBody.WORLD_TIME);
      if (nanos >= 0) {
        out.emit(PHASE, new Phase(DistributedGait.phase(nanos / 1e9, index, count), nanos));
      }
    }
  }

  /**
   * The two lower legs row in opposite phase, swinging as far as the gait says for the world time
   * of the phase: a swing given {@link #from} a time on applies to the readings of that time and
   * later only, whenever the module was built, so that the commands answering a reading do not
   * depend on when the robot's island applied the request.
   */
  static final class Gait implements Reactor {
    private final String name;
    private final NavigableMap<Long, Double> swings;

    /** A gait swinging {@code swing} rad from the start. */
    Gait(String name, double swing) {
      this(name, new TreeMap<>(Map.of(Long.MIN_VALUE, DistributedGait.checkSwing(swing))));
    }

    private Gait(String name, NavigableMap<Long, Double> swings) {
      this.name = requireNonNull(name, "name");
      this.swings = swings;
    }

    /**
     * This gait, swinging {@code swing} rad for the readings of world time {@code fromNanos} and
     * later.
     *
     * @throws IllegalArgumentException a negative time, or a swing the cone does not allow
     */
    Gait from(long fromNanos, double swing) {
      if (fromNanos < 0) {
        throw new IllegalArgumentException(
            "gait " + name + ": " + FROM + " " + fromNanos + ": expected a world time >= 0 ns");
      }
      NavigableMap<Long, Double> next = new TreeMap<>(swings);
      next.put(fromNanos, DistributedGait.checkSwing(swing));
      return new Gait(name, next);
    }

    /** The swing for the readings of world time {@code nanos}, rad. */
    double swingAt(long nanos) {
      return swings.floorEntry(nanos).getValue();
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of(PHASE);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STRIDE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Phase phase = in.get(PHASE);
      if (phase != null) {
        double swing = swingAt(phase.timeNanos());
        double other = (phase.value() + 0.5) % 1.0;
        out.emit(
            STRIDE,
            new Stride(
                DistributedGait.leg(
                    phase.value(), DistributedGait.FRONT_MZ, DistributedGait.OUT_MZ, swing),
                DistributedGait.leg(other, DistributedGait.FRONT_MY, DistributedGait.OUT_MY, swing),
                swing));
      }
    }

    @Override
    public String toString() {
      return name + swings.tailMap(Long.MIN_VALUE, false);
    }
  }

  /** Sends the stride to the legs. */
  record LegDrive(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(STRIDE);
    }

    @Override
    public void act(Inputs in, Body body) {
      Stride stride = in.get(STRIDE);
      if (stride != null) {
        body.command(Atom.target(Leg.MZ), stride.minusZ());
        body.command(Atom.target(Leg.MY), stride.minusY());
      }
    }
  }
}
