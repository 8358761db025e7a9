package org.armgals.examples.robots;

import static org.armgals.examples.robots.ReconfigureModules.BEAT;
import static org.armgals.examples.robots.ReconfigureModules.HEARD;
import static org.armgals.examples.robots.ReconfigureModules.STRIDE;

import java.util.ArrayList;
import java.util.List;
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
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Adaptation;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.BehaviorModule;
import org.armgals.maam.Connector;
import org.armgals.maam.Derivator;
import org.armgals.maam.PortRef;
import org.armgals.maam.Schema;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;

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
 * The meta level changes these with the body's shape: {@link #detach}, then {@link #becomeHead} or
 * {@link #becomeTail}.
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
    Feet feet = new Feet("feet");
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
      Pacemaker pacemaker = new Pacemaker("pacemaker", periodNanos, 0, 0);
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

  /** Lets {@code meta} watch and adapt this atom's robot. */
  void watchedBy(BMetaRobot meta) {
    setBehavioralMeta(meta);
  }

  /** The adaptation that adds the {@value #DETACH} schema, releasing the bond on {@code leg}. */
  Adaptation detach(Leg leg) {
    return new Adaptation.AddSchema(Schema.builder(DETACH).add(new Detach("detach", leg)).build());
  }

  /**
   * The adaptations that make a follower the head of a molecule of its own: its {@value #FOLLOW}
   * schema gives way to {@value #PACE}, whose pacemaker goes on from {@code phase} at full stride;
   * the {@value #DETACH} schema goes.
   */
  List<Adaptation> becomeHead(double phase) {
    Pacemaker pacemaker = new Pacemaker("pacemaker", periodNanos, phase, 1);
    List<Adaptation> all = new ArrayList<>();
    all.add(new Adaptation.RemoveSchema(DETACH));
    all.add(new Adaptation.RemoveSchema(FOLLOW));
    all.add(new Adaptation.AddSchema(Schema.builder(PACE).add(pacemaker).build()));
    beatFrom(pacemaker, true).forEach(c -> all.add(new Adaptation.AddConnector(c)));
    return all;
  }

  /** The adaptations that make an atom the tail of its molecule: no relay, no detach. */
  List<Adaptation> becomeTail() {
    return List.of(new Adaptation.RemoveSchema(DETACH), new Adaptation.RemoveSchema(RELAY));
  }

  /** The derivators that feed {@code source}'s beat to the crawl, and to the relay if any. */
  private List<Connector> beatFrom(BehaviorModule source, boolean relayed) {
    Derivator toCrawl = new Derivator(PortRef.of(source, BEAT), PortRef.of(crawl, BEAT));
    return relayed
        ? List.of(toCrawl, new Derivator(PortRef.of(source, BEAT), PortRef.of(relay, BEAT)))
        : List.of(toCrawl);
  }
}
