package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.armgals.examples.robots.ReconfigureSignals.Beat;
import org.armgals.examples.robots.ReconfigureSignals.Bonds;
import org.armgals.examples.robots.ReconfigureSignals.Walls;
import org.armgals.examples.sim.Journal;
import org.armgals.maam.Adaptation;
import org.armgals.maam.CycleReport;
import org.jspecify.annotations.Nullable;

/**
 * The behavioral meta level of {@link Reconfigure}'s chain, notified by every atom's robot. Its
 * model: how long the front atom has seen walls on both sides, each atom's bonds and beat. Its
 * rule:
 *
 * <ol>
 *   <li>when the front atom has seen both walls for {@value ReconfigureTuning#CORRIDOR_SECONDS} s
 *       (a corridor), split the chain in the middle: add the {@value ReconfigureAtom#DETACH} schema
 *       to the two atoms of the middle bond;
 *   <li>when both have sensed the bond gone, reconfigure the software with the body: the rear
 *       pair's front atom replaces {@value ReconfigureAtom#FOLLOW} by {@value ReconfigureAtom#PACE}
 *       (it is a head now, going on from the phase it followed), the front pair's rear atom removes
 *       its {@value ReconfigureAtom#RELAY} (no one is behind it); both drop the detach schema.
 * </ol>
 *
 * Each adaptation is told to the journal with what the meta level saw. Called on the simulation's
 * thread, from the robots' cycles.
 */
final class ReconfigureMeta {
  /** Where the chain splits: between the atoms at these places, 0 at the rear. */
  static final int REAR_HEAD = ReconfigureTuning.ATOMS / 2 - 1;

  static final int FRONT_TAIL = REAR_HEAD + 1;

  /** What the meta level has done. */
  enum Stage {
    CHAIN,
    SPLITTING,
    SPLIT
  }

  private final Journal journal;
  private final long periodNanos;
  private final List<ReconfigureAtom> robots = new ArrayList<>();
  private final List<Integer> atomIds = new ArrayList<>();
  private final List<@Nullable Bonds> bonds = new ArrayList<>();
  private final List<@Nullable Beat> beats = new ArrayList<>();
  private Stage stage = Stage.CHAIN;
  private long wallsSince = -1;
  private long splitAt = -1;

  ReconfigureMeta(Journal journal, long periodNanos) {
    this.journal = requireNonNull(journal, "journal");
    this.periodNanos = periodNanos;
  }

  /** Watches the robot of the next atom of the chain, rear first; the last is the front. */
  void watch(int atomId, ReconfigureAtom robot) {
    int index = robots.size();
    atomIds.add(atomId);
    robots.add(requireNonNull(robot, "robot"));
    bonds.add(null);
    beats.add(null);
    robot.watchedBy((report, requests) -> onCycle(index, report, requests));
  }

  /** What it has done so far. */
  Stage stage() {
    return stage;
  }

  /** When it decided to split the chain (ns of virtual time), or −1. */
  long splitAt() {
    return splitAt;
  }

  private void onCycle(int index, CycleReport report, Consumer<Adaptation> requests) {
    @Nullable Walls walls = null;
    for (CycleReport.Emission e : report.emissions()) {
      switch (e.signal()) {
        case Bonds b -> bonds.set(index, b);
        case Beat b -> beats.set(index, b);
        case Walls w -> walls = w;
        default -> {}
      }
    }
    if (stage == Stage.CHAIN && index == robots.size() - 1) {
      watchWalls(walls, report.nanoTime());
    } else if (stage == Stage.SPLITTING && index == REAR_HEAD && middleBondGone()) {
      reconfigure(requests);
    }
  }

  private void watchWalls(@Nullable Walls walls, long now) {
    if (walls == null) {
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
            walls.left(),
            walls.right(),
            seen);
    robots.get(REAR_HEAD).request(robots.get(REAR_HEAD).detach(ReconfigureModules.AHEAD));
    journal.adaptation(atomIds.get(REAR_HEAD), "added schema detach (+x bond)", why);
    robots.get(FRONT_TAIL).request(robots.get(FRONT_TAIL).detach(ReconfigureModules.BEHIND));
    journal.adaptation(atomIds.get(FRONT_TAIL), "added schema detach (-x bond)", why);
  }

  private boolean middleBondGone() {
    Bonds rear = bonds.get(REAR_HEAD);
    Bonds front = bonds.get(FRONT_TAIL);
    return rear != null && front != null && rear.ahead().isEmpty() && front.behind().isEmpty();
  }

  private void reconfigure(Consumer<Adaptation> requests) {
    stage = Stage.SPLIT;
    Beat beat = beats.get(REAR_HEAD);
    double phase = (beat == null ? 0 : beat.phase()) + ReconfigureTuning.advance(periodNanos);
    robots.get(REAR_HEAD).becomeHead(phase % (2 * Math.PI)).forEach(requests);
    journal.adaptation(
        atomIds.get(REAR_HEAD),
        "replaced schema follow by pace, removed schema detach",
        "its +x bond is gone (binding sensor): it heads the rear pair and beats its own rhythm");
    ReconfigureAtom tail = robots.get(FRONT_TAIL);
    tail.becomeTail().forEach(tail::request);
    journal.adaptation(
        atomIds.get(FRONT_TAIL),
        "removed schemas relay and detach",
        "its -x bond is gone (binding sensor): no atom behind it to pass the rhythm to");
  }
}
