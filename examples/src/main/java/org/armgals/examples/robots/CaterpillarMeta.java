package org.armgals.examples.robots;

import static org.armgals.examples.robots.CaterpillarSignals.BEAT;
import static org.armgals.examples.robots.CaterpillarSignals.TRAVEL;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.armgals.examples.robots.CaterpillarModules.Pacemaker;
import org.armgals.examples.robots.CaterpillarSignals.Beat;
import org.armgals.examples.robots.CaterpillarSignals.Travel;
import org.armgals.examples.sim.Journal;
import org.armgals.maam.Adaptation;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.CycleReport;

/**
 * The head's behavioral meta level (paper §5.4): from each cycle's report it follows the head's
 * beat and position, sums up the progress of every step, and when a step brought less than {@link
 * CaterpillarTuning#SLOW_STEP}, asks for a longer stride: a {@code changeModule} of the head's
 * pacemaker, which the head then passes down the chain with its rhythm. It waits {@link
 * CaterpillarTuning#DWELL_STEPS} steps after each change before judging again, so that a change is
 * judged on steps made with it. Called on the head's thread, once a cycle.
 */
final class CaterpillarMeta implements BMetaRobot {
  private final Pacemaker prototype;
  private final Journal journal;
  private final int atom;
  private final List<String> changes = new ArrayList<>();
  private double stride;
  private double lastPhase = -1;
  private double stepStartX = Double.NaN;
  private int stepsSinceChange;
  private int steps;

  /**
   * @param prototype the head's pacemaker as built: the meta level asks for copies of it
   * @param journal where adaptations are told
   * @param atom the head's atom id, for the journal
   */
  CaterpillarMeta(Pacemaker prototype, Journal journal, int atom) {
    this.prototype = prototype;
    this.journal = journal;
    this.atom = atom;
    this.stride = prototype.stride();
  }

  @Override
  public void onCycle(CycleReport report, Consumer<Adaptation> requests) {
    Beat beat = null;
    Travel travel = null;
    for (CycleReport.Emission e : report.emissions()) {
      if (e.port().port().equals(BEAT)) {
        beat = (Beat) e.signal();
      } else if (e.port().port().equals(TRAVEL)) {
        travel = (Travel) e.signal();
      }
    }
    if (beat == null || travel == null) {
      return;
    }
    boolean newStep = beat.phase() < lastPhase;
    lastPhase = beat.phase();
    if (!newStep) {
      return;
    }
    if (Double.isNaN(stepStartX)) {
      stepStartX = travel.x();
      return;
    }
    double progress = travel.x() - stepStartX;
    stepStartX = travel.x();
    steps++;
    stepsSinceChange++;
    if (stepsSinceChange >= CaterpillarTuning.DWELL_STEPS
        && progress < CaterpillarTuning.SLOW_STEP
        && stride < CaterpillarTuning.MAX_STRIDE - 1e-9) {
      double longer =
          Math.min(CaterpillarTuning.MAX_STRIDE, stride + CaterpillarTuning.STRIDE_STEP);
      requests.accept(new Adaptation.ChangeModule(prototype.withStride(longer, beat.phase())));
      String what =
          String.format(Locale.ROOT, "stride %.2f -> %.2f rad (pacemaker changed)", stride, longer);
      String why =
          String.format(
              Locale.ROOT,
              "step %d advanced %.1f cm, less than %.1f cm",
              steps,
              progress * 100,
              CaterpillarTuning.SLOW_STEP * 100);
      journal.adaptation(atom, what, why);
      changes.add(what);
      stride = longer;
      stepsSinceChange = 0;
    }
  }

  /** The stride the head beats now, radians. */
  double stride() {
    return stride;
  }

  /** The steps the meta level judged. */
  int steps() {
    return steps;
  }

  /** The changes it asked for, in order. */
  List<String> changes() {
    return List.copyOf(changes);
  }
}
