package org.armgals.examples.robots;

import static org.armgals.examples.robots.ReconfigureModules.BEAT;
import static org.armgals.examples.robots.ReconfigureModules.HEARD;
import static org.armgals.examples.robots.ReconfigureModules.STRIDE;

import java.util.List;
import java.util.Map;
import org.armgals.active.TimeSource;
import org.armgals.examples.robots.ObstacleModules.Feet;
import org.armgals.examples.robots.ReconfigureModules.Chain;
import org.armgals.examples.robots.ReconfigureModules.Crawl;
import org.armgals.examples.robots.ReconfigureModules.Detach;
import org.armgals.examples.robots.ReconfigureModules.Follow;
import org.armgals.examples.robots.ReconfigureModules.Listen;
import org.armgals.examples.robots.ReconfigureModules.Pacemaker;
import org.armgals.examples.robots.ReconfigureModules.Relay;
import org.armgals.examples.robots.ReconfigureModules.Survey;
import org.armgals.examples.robots.ReconfigureSignals.Beat;
import org.armgals.examples.robots.ReconfigureSignals.Bonds;
import org.armgals.examples.robots.ReconfigureSignals.Walls;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.BehaviorModule;
import org.armgals.maam.Connector;
import org.armgals.maam.Derivator;
import org.armgals.maam.Emission;
import org.armgals.maam.PortRef;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.representation.p.PState;

/**
 * The robot of one atom of {@link Reconfigure}'s chain. Its schemas follow its place in the
 * molecule: a head runs {@value #PACE}, a follower {@value #FOLLOW}; an atom with a neighbour
 * behind runs {@value #RELAY}; the front atom runs {@value #SURVEY}; all run {@value #CRAWL}.
 *
 * <pre>{@code
 * crawl:   chain --bonds-->        crawl --stride--> feet
 * pace:    pacemaker  ==D==> crawl.beat, relay.beat          (a head)
 * follow:  listen --heard--> follow  ==D==> crawl.beat, relay.beat   (a follower)
 * relay:   relay (sends the beat through the back bond)      (an atom with one behind)
 * survey:  survey --walls-->                                 (the front atom)
 * detach:  detach (releases one chain bond)                  (added by the meta level)
 * }</pre>
 *
 * The meta level changes these with the body's shape, by requests naming the parts of the atoms'
 * kind ({@link #kind}): {@value #DETACH}, then a new head's {@value #PACE} or a tail without
 * {@value #RELAY}.
 */
final class ReconfigureAtom extends AbstractRobot {
  static final String CRAWL = "crawl";
  static final String PACE = "pace";
  static final String FOLLOW = "follow";
  static final String RELAY = "relay";
  static final String SURVEY = "survey";
  static final String DETACH = "detach";

  private final long periodNanos;
  private final Crawl crawl = new Crawl("crawl");
  private final Relay relay = new Relay("relay");

  /**
   * @param id the atom's id in the scene
   * @param head whether it beats the rhythm (the front atom)
   * @param tail whether no atom is behind it (the rear atom)
   */
  ReconfigureAtom(
      int id, Body body, TimeSource time, long periodNanos, boolean head, boolean tail) {
    super("atom-" + id, body, time);
    this.periodNanos = periodNanos;
    Feet feet = new Feet("feet", ReconfigureTuning.FOOT_SLEW);
    addSchema(
        Schema.builder(CRAWL)
            .add(new Chain("chain"))
            .add(crawl)
            .add(feet)
            .wire(crawl, STRIDE, feet, STRIDE)
            .build());
    if (!tail) {
      addSchema(Schema.builder(RELAY).add(relay).build());
    }
    if (head) {
      Pacemaker pacemaker = new Pacemaker(PACEMAKER, periodNanos, 0, 0);
      addSchema(Schema.builder(PACE).add(pacemaker).build());
      beatFrom(pacemaker, !tail).forEach(this::addConnector);
      addSchema(Schema.builder(SURVEY).add(new Survey("survey")).build());
    } else {
      Listen listen = new Listen("listen");
      Follow follow = new Follow("follow", periodNanos);
      addSchema(
          Schema.builder(FOLLOW)
              .add(listen)
              .add(follow)
              .wire(listen, HEARD, follow, HEARD)
              .build());
      beatFrom(follow, !tail).forEach(this::addConnector);
    }
  }

  /** Observed: the atom ahead is bound to it. */
  static final String BOND_AHEAD = "bondAhead";

  /** Observed: the atom behind is bound to it. */
  static final String BOND_BEHIND = "bondBehind";

  /** Observed: the phase of the beat it crawls to, -1 with none. */
  static final String PHASE = "phase";

  /** Observed: how near a wall its left side leg sees, metres; -1 with none. */
  static final String WALL_LEFT = "wallLeft";

  /** Observed: how near a wall its right side leg sees, metres; -1 with none. */
  static final String WALL_RIGHT = "wallRight";

  /** The leg of a bond, {@code PX} or {@code MX}, in a request for {@value #DETACH}. */
  static final String LEG = "leg";

  /** The connectors that feed a new head's beat to its crawl and its relay. */
  static final List<String> PACE_CONNECTORS = List.of("pace-to-crawl", "pace-to-relay");

  /**
   * The kind of the chain's atoms, {@code ReconfigureAtom}: they observe their bonds, their beat
   * and the walls they see; its catalog has {@value #DETACH} (releasing the bond of a {@value
   * #LEG}), {@value #PACE} (a pacemaker going on from a {@value #PHASE} at full stride) and the
   * connectors that feed its beat ({@link #PACE_CONNECTORS}).
   */
  static StructuralMeta<PState> kind(Kernel kernel) {
    return RobotKind.builder("ReconfigureAtom", ReconfigureAtom.class)
        .observing(
            Map.of(
                BOND_AHEAD, false,
                BOND_BEHIND, false,
                PHASE, -1.0,
                WALL_LEFT, -1.0,
                WALL_RIGHT, -1.0))
        .schema(
            DETACH,
            (atom, p) -> Schema.builder(DETACH).add(new Detach("detach", leg(p.text(LEG)))).build())
        .schema(
            PACE,
            (atom, p) ->
                Schema.builder(PACE)
                    .add(new Pacemaker(PACEMAKER, atom.periodNanos, p.number(PHASE), 1))
                    .build())
        .connector(
            PACE_CONNECTORS.get(0),
            (atom, p) -> new Derivator(new PortRef(PACEMAKER, BEAT), PortRef.of(atom.crawl, BEAT)))
        .connector(
            PACE_CONNECTORS.get(1),
            (atom, p) -> new Derivator(new PortRef(PACEMAKER, BEAT), PortRef.of(atom.relay, BEAT)))
        .define(kernel);
  }

  private static final String PACEMAKER = "pacemaker";

  private static Leg leg(String name) {
    for (Leg leg : Leg.values()) {
      if (leg.name().equals(name)) {
        return leg;
      }
    }
    throw new IllegalArgumentException(
        "leg '" + name + "': expected one of " + java.util.Arrays.toString(Leg.values()));
  }

  /** What an atom shows its meta level: its bonds, its beat, the walls it sees. */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    boolean ahead = false;
    boolean behind = false;
    double phase = -1;
    double left = -1;
    double right = -1;
    for (Emission e : emissions()) {
      switch (e.signal()) {
        case Bonds b -> {
          ahead = b.ahead().isPresent();
          behind = b.behind().isPresent();
        }
        case Beat b -> phase = b.phase();
        case Walls w -> {
          left = w.left();
          right = w.right();
        }
        default -> {}
      }
    }
    m.put(BOND_AHEAD, ahead);
    m.put(BOND_BEHIND, behind);
    m.put(PHASE, phase);
    m.put(WALL_LEFT, left);
    m.put(WALL_RIGHT, right);
    return m;
  }

  /** The derivators that feed {@code source}'s beat to the crawl, and to the relay if any. */
  private List<Connector> beatFrom(BehaviorModule source, boolean relayed) {
    Derivator toCrawl = new Derivator(PortRef.of(source, BEAT), PortRef.of(crawl, BEAT));
    return relayed
        ? List.of(toCrawl, new Derivator(PortRef.of(source, BEAT), PortRef.of(relay, BEAT)))
        : List.of(toCrawl);
  }
}
