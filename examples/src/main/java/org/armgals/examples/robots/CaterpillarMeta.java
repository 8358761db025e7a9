package org.armgals.examples.robots;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.armgals.examples.robots.CaterpillarModules.Pacemaker;
import org.armgals.kernel.Notification;
import org.armgals.kernel.StateEvent;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.maam.RobotKind;

/**
 * The head's behavioral meta level (paper §5.4, figure 8: {@code bmrobot}), the policy of a kernel
 * behavioral meta-entity: from the head's state events (its beat's phase and how far it has
 * travelled, {@link CaterpillarSegment#observe()}) it sums up the progress of every step, and when
 * a step brought less than {@link CaterpillarTuning#SLOW_STEP}, asks for a longer stride: a {@code
 * changeModule} of the head's pacemaker, which the head then passes down the chain with its rhythm.
 * It waits {@link CaterpillarTuning#DWELL_STEPS} steps after each change before judging again, so
 * that a change is judged on steps made with it.
 *
 * <p>Threading: runs on its meta-entity's own object, never on the head's thread; the head applies
 * its requests at its adaptation point ({@link CaterpillarSegment#adapted}), where the reasons are
 * taken for the journal. The figures are read once the meta has settled.
 */
final class CaterpillarMeta implements MetaPolicy {
  private final Pacemaker prototype;
  private final ConcurrentLinkedQueue<String[]> reasons = new ConcurrentLinkedQueue<>();
  private final List<String> changes = new ArrayList<>();
  private volatile double stride;
  private volatile int steps;
  private double lastPhase = -1;
  private double stepStartX = Double.NaN;
  private int stepsSinceChange;

  /**
   * @param prototype the head's pacemaker as built: the meta level asks for copies of it
   */
  CaterpillarMeta(Pacemaker prototype) {
    this.prototype = prototype;
    this.stride = prototype.stride();
  }

  @Override
  public void onNotification(MetaContext context, Notification notification) {
    if (!(notification instanceof StateEvent s)) {
      return;
    }
    Map<String, Object> seen = s.observation();
    if (!(seen.get(CaterpillarSegment.PHASE) instanceof Double phase)
        || !(seen.get(CaterpillarSegment.X) instanceof Double x)
        || phase < 0) {
      return;
    }
    boolean newStep = phase < lastPhase;
    lastPhase = phase;
    if (!newStep) {
      return;
    }
    if (Double.isNaN(stepStartX)) {
      stepStartX = x;
      return;
    }
    double progress = x - stepStartX;
    stepStartX = x;
    steps++;
    stepsSinceChange++;
    if (stepsSinceChange >= CaterpillarTuning.DWELL_STEPS
        && progress < CaterpillarTuning.SLOW_STEP
        && stride < CaterpillarTuning.MAX_STRIDE - 1e-9) {
      double longer =
          Math.min(CaterpillarTuning.MAX_STRIDE, stride + CaterpillarTuning.STRIDE_STEP);
      String what =
          String.format(Locale.ROOT, "stride %.2f -> %.2f rad (pacemaker changed)", stride, longer);
      String why =
          String.format(
              Locale.ROOT,
              "step %d advanced %.1f cm, less than %.1f cm",
              steps,
              progress * 100,
              CaterpillarTuning.SLOW_STEP * 100);
      var change =
          RobotKind.changeModule(
              CaterpillarSegment.PACEMAKER,
              Map.of(CaterpillarSegment.STRIDE, longer, CaterpillarSegment.PHASE, phase));
      if (context.adapt(s.entity(), change).isPresent()) {
        reasons.add(new String[] {what, why});
        changes.add(what);
        stride = longer;
        stepsSinceChange = 0;
      }
    }
  }

  /** What the oldest change not yet applied was, and why it was asked for; null if none. */
  String[] nextReason() {
    return reasons.poll();
  }

  /** The stride the head beats now, radians. */
  double stride() {
    return stride;
  }

  /** The steps the meta level judged. */
  int steps() {
    return steps;
  }
}
