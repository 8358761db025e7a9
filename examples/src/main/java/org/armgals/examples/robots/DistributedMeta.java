package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.concurrent.ConcurrentHashMap;
import org.armgals.active.Address;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Notification;
import org.armgals.kernel.ThresholdEvent;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;

/**
 * The behavioral meta level of {@link Distributed}'s chain: the paper's battery example (§2.3, §4)
 * across JVMs. One behavioral meta-entity of the world's kernel, {@value #NAME}, takes every atom's
 * robot, each in a JVM of its own; its filter, a JMS selector, takes threshold meta-events only
 * ({@value #THRESHOLDS_ONLY}), so the state events the robots send each cycle feed its models and
 * nothing else. On the meta-event that an atom's battery fell under {@link
 * DistributedCrawler#LOW_BATTERY} it asks that atom, once, for a gentler stroke ({@value
 * #GENTLE_SWING} rad instead of {@value DistributedGait#SWING}) by a {@code changeModule} of its
 * {@value DistributedCrawler#GAIT}, which names the world time from which the new swing applies:
 * the readings of the cycle after the threshold's ({@link #applyFrom}).
 *
 * <p>Why a time: the atom's island runs on real time, so when the request reaches it depends on the
 * broker and the machine's load; the world's lock step waits, before it sends the readings of a
 * cycle, until this meta has handled every notification of the readings before and each atom has
 * acknowledged every request ({@link DistributedMetaLevel#keepUp}), so the readings of the named
 * time are the first the new swing answers, in every run.
 *
 * <p>Threading: {@link #onNotification} on its meta-entity's own object, never on a robot's thread
 * (nor in a robot's JVM); {@link #decisions} on any thread.
 */
final class DistributedMeta extends BMetaRobot {
  /** Its meta-entity's name. */
  static final String NAME = "bmcrawler";

  /** Its filter of every robot's notifications. */
  static final String THRESHOLDS_ONLY = "kind = 'threshold'";

  /** The swing it asks for when an atom's battery runs low, rad. */
  static final double GENTLE_SWING = 0.25;

  /**
   * What it asked of one robot.
   *
   * @param robot the robot's name
   * @param version the request's version
   * @param thresholdNanos the world time of the readings the threshold was crossed on
   * @param fraction the fraction of a full battery left then
   * @param fromNanos the world time from whose readings on the gentler swing applies
   * @param swing the swing asked for, rad
   * @param reason why, as the request says ({@link RobotKind#because})
   */
  record Decision(
      String robot,
      long version,
      long thresholdNanos,
      double fraction,
      long fromNanos,
      double swing,
      String reason) {
    /** Checks the names. */
    Decision {
      requireNonNull(robot, "robot");
      requireNonNull(reason, "reason");
    }
  }

  private final long periodNanos;
  private final Map<String, Decision> decisions = new ConcurrentHashMap<>();

  /**
   * @param periodNanos the world's control period: a request names the readings of the cycle after
   *     the threshold's
   */
  DistributedMeta(long periodNanos) {
    super(NAME, Damping.none());
    if (periodNanos <= 0) {
      throw new IllegalArgumentException("period " + periodNanos + " ns: expected > 0");
    }
    this.periodNanos = periodNanos;
  }

  /**
   * The world time from whose readings on a request decided on the readings of {@code nanos}
   * applies: the next cycle's.
   */
  long applyFrom(long nanos) {
    return nanos + periodNanos;
  }

  @Override
  public void onNotification(MetaContext context, Notification n) {
    if (n instanceof ThresholdEvent t
        && t.below()
        && t.threshold().equals(DistributedCrawler.LOW_BATTERY.name())) {
      String robot = context.entity(t.entity()).name();
      if (!decisions.containsKey(robot)) {
        lower(context, t.entity(), robot, t);
      }
    }
  }

  private void lower(MetaContext context, Address entity, String robot, ThresholdEvent t) {
    long from = applyFrom(t.nanoTime());
    String why =
        String.format(
            Locale.ROOT,
            "battery at %.1f%% (threshold meta-event '%s' at %.2f s): a gentler stroke, %.2f rad",
            100 * t.value(),
            t.threshold(),
            t.nanoTime() / 1e9,
            GENTLE_SWING);
    var request =
        RobotKind.because(
            why,
            RobotKind.changeModule(
                DistributedCrawler.GAIT,
                Map.of(DistributedCrawler.SWING, GENTLE_SWING, DistributedCrawler.FROM, from)));
    OptionalLong version = context.adapt(entity, request);
    if (version.isPresent()) { // no damping holds it back: Damping.none()
      decisions.put(
          robot,
          new Decision(
              robot, version.getAsLong(), t.nanoTime(), t.value(), from, GENTLE_SWING, why));
    }
  }

  /** What it asked of robot {@code robot}, if anything. */
  Optional<Decision> decision(String robot) {
    return Optional.ofNullable(decisions.get(requireNonNull(robot, "robot")));
  }

  /** What it asked, by robot, in no particular order. */
  List<Decision> decisions() {
    return List.copyOf(decisions.values());
  }
}
