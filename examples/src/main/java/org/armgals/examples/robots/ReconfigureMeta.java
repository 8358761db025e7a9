package org.armgals.examples.robots;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Notification;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;

/**
 * The behavioral meta level of {@link Reconfigure}'s chain, a behavioral meta-entity of the kernel
 * taking every atom's robot, notified of their states (bonds, beat, walls seen). Its model: how
 * long the front atom has seen walls on both sides, each atom's bonds and beat. Its rule:
 *
 * <ol>
 *   <li>when the front atom has seen both walls for {@value ReconfigureTuning#CORRIDOR_SECONDS} s
 *       (a corridor), split the chain in the middle: ask the two atoms of the middle bond for the
 *       {@value ReconfigureAtom#DETACH} schema;
 *   <li>when both have sensed the bond gone, reconfigure the software with the body: the rear
 *       pair's front atom replaces {@value ReconfigureAtom#FOLLOW} by {@value ReconfigureAtom#PACE}
 *       (it is a head now, going on from the phase it followed), the front pair's rear atom removes
 *       its {@value ReconfigureAtom#RELAY} (no one is behind it); both drop the detach schema.
 * </ol>
 *
 * Each request says what the meta level saw. Runs on its meta-entity's own object, in the chain's
 * JVM or another.
 */
final class ReconfigureMeta extends BMetaRobot {
  /** Where the chain splits: between the atoms at these places, 0 at the rear. */
  static final int REAR_HEAD = ReconfigureTuning.ATOMS / 2 - 1;

  static final int FRONT_TAIL = REAR_HEAD + 1;

  /** What the meta level has done. */
  enum Stage {
    CHAIN,
    SPLITTING,
    SPLIT
  }

  private final List<String> robots;
  private final long periodNanos;
  private final boolean[] ahead;
  private final boolean[] behind;
  private final double[] phase;
  private volatile Stage stage = Stage.CHAIN;
  private long wallsSince = -1;
  private volatile long splitAt = -1;

  /**
   * @param robots the names of the atoms' robots, rear first
   */
  ReconfigureMeta(List<String> robots, long periodNanos) {
    super("bmchain", Damping.none());
    this.robots = List.copyOf(robots);
    this.periodNanos = periodNanos;
    this.ahead = new boolean[robots.size()];
    this.behind = new boolean[robots.size()];
    this.phase = new double[robots.size()];
  }

  /** What it has done so far. */
  Stage stage() {
    return stage;
  }

  /** When it decided to split the chain (ns of the base level's time), or −1. */
  long splitAt() {
    return splitAt;
  }

  @Override
  public void onNotification(MetaContext context, Notification n) {
    Map<String, Object> seen = observation(n).orElse(null);
    int index = robots.indexOf(context.entity(n.entity()).name());
    if (seen == null || index < 0) {
      return;
    }
    ahead[index] = (Boolean) seen.get(ReconfigureAtom.BOND_AHEAD);
    behind[index] = (Boolean) seen.get(ReconfigureAtom.BOND_BEHIND);
    phase[index] = (Double) seen.get(ReconfigureAtom.PHASE);
    if (stage == Stage.CHAIN && index == robots.size() - 1) {
      double left = (Double) seen.get(ReconfigureAtom.WALL_LEFT);
      double right = (Double) seen.get(ReconfigureAtom.WALL_RIGHT);
      watchWalls(context, left, right);
    } else if (stage == Stage.SPLITTING
        && index == REAR_HEAD
        && !ahead[REAR_HEAD]
        && !behind[FRONT_TAIL]) {
      reconfigure(context);
    }
  }

  private void watchWalls(MetaContext context, double left, double right) {
    long now = context.nanoTime();
    if (left < 0 || right < 0) {
      wallsSince = -1;
      return;
    }
    if (wallsSince < 0) {
      wallsSince = now;
    }
    double seen = (now - wallsSince) / 1e9;
    if (seen + 1e-9 < ReconfigureTuning.CORRIDOR_SECONDS) {
      return;
    }
    stage = Stage.SPLITTING;
    splitAt = now;
    String why =
        String.format(
            Locale.ROOT,
            "the front atom sees walls on both sides (%.2f m, %.2f m) for %.1f s: a corridor,"
                + " go on as two pairs",
            left,
            right,
            seen);
    ask(
        context,
        REAR_HEAD,
        why,
        RobotKind.addSchema(ReconfigureAtom.DETACH, Map.of(ReconfigureAtom.LEG, "PX")));
    ask(
        context,
        FRONT_TAIL,
        why,
        RobotKind.addSchema(ReconfigureAtom.DETACH, Map.of(ReconfigureAtom.LEG, "MX")));
  }

  private void reconfigure(MetaContext context) {
    stage = Stage.SPLIT;
    double from =
        (phase[REAR_HEAD] < 0 ? 0 : phase[REAR_HEAD]) + ReconfigureTuning.advance(periodNanos);
    String head =
        "its +x bond is gone (binding sensor): it heads the rear pair and beats its own rhythm";
    ask(context, REAR_HEAD, head, RobotKind.removeSchema(ReconfigureAtom.DETACH));
    ask(context, REAR_HEAD, head, RobotKind.removeSchema(ReconfigureAtom.FOLLOW));
    ask(
        context,
        REAR_HEAD,
        head,
        RobotKind.addSchema(
            ReconfigureAtom.PACE, Map.of(ReconfigureAtom.PHASE, from % (2 * Math.PI))));
    for (String connector : ReconfigureAtom.PACE_CONNECTORS) {
      ask(context, REAR_HEAD, head, RobotKind.addConnector(connector, Map.of()));
    }
    String tail = "its -x bond is gone (binding sensor): no atom behind it to pass the rhythm to";
    ask(context, FRONT_TAIL, tail, RobotKind.removeSchema(ReconfigureAtom.DETACH));
    ask(context, FRONT_TAIL, tail, RobotKind.removeSchema(ReconfigureAtom.RELAY));
  }

  private void ask(
      MetaContext context, int index, String why, org.armgals.kernel.Adaptation request) {
    for (Entity atom : context.self().baseLevelEntities()) {
      if (atom.name().equals(robots.get(index))) {
        context.adapt(atom.address(), RobotKind.because(why, request));
        return;
      }
    }
    throw new IllegalStateException("no atom " + robots.get(index) + " among " + robots);
  }
}
