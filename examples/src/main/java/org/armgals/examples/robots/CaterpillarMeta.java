package org.armgals.examples.robots;

import java.time.Duration;
import java.util.Locale;
import java.util.Map;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Notification;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;

/**
 * The head's behavioral meta level (paper §5.4, figure 8: {@code bmrobot}), a behavioral
 * meta-entity of the kernel: from the head's state (its beat's phase and how far it has travelled,
 * {@link CaterpillarSegment#observe()}) it sums up the progress of every step, and when a step
 * brought less than {@link CaterpillarTuning#SLOW_STEP}, asks for a longer stride: a {@code
 * changeModule} of the head's pacemaker, which the head then passes down the chain with its rhythm.
 * Its damping keeps it from changing the stride again before {@link CaterpillarTuning#DWELL_STEPS}
 * steps have been made with the last change, so that a change is judged on steps made with it.
 *
 * <p>Threading: runs on its meta-entity's own object, never on the head's thread, in the head's JVM
 * or another; the head applies its requests at its adaptation point. Its figures are read once the
 * run is over.
 */
final class CaterpillarMeta extends BMetaRobot {
  private volatile double stride = CaterpillarTuning.START_STRIDE;
  private volatile int steps;
  private double lastPhase = -1;
  private double stepStartX = Double.NaN;

  CaterpillarMeta(String name) {
    super(
        name,
        new Damping(
            Duration.ofMillis(
                Math.round(CaterpillarTuning.DWELL_STEPS * CaterpillarTuning.PERIOD * 1000)),
            Integer.MAX_VALUE,
            Duration.ofSeconds(1)));
  }

  @Override
  public void onNotification(MetaContext context, Notification notification) {
    Map<String, Object> seen = observation(notification).orElse(Map.of());
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
    if (progress >= CaterpillarTuning.SLOW_STEP || stride >= CaterpillarTuning.MAX_STRIDE - 1e-9) {
      return;
    }
    double longer = Math.min(CaterpillarTuning.MAX_STRIDE, stride + CaterpillarTuning.STRIDE_STEP);
    String why =
        String.format(
            Locale.ROOT,
            "step %d advanced %.1f cm, less than %.1f cm: stride %.2f -> %.2f rad",
            steps,
            progress * 100,
            CaterpillarTuning.SLOW_STEP * 100,
            stride,
            longer);
    var change =
        RobotKind.because(
            why,
            RobotKind.changeModule(
                CaterpillarSegment.PACEMAKER,
                Map.of(
                    CaterpillarSegment.STRIDE,
                    longer,
                    CaterpillarSegment.PHASE,
                    // To a millionth of a step: the beat's sum of cycles leaves crumbs below it.
                    Math.round(phase * 1e6) / 1e6)));
    if (context.adapt(notification.entity(), change).isPresent()) {
      stride = longer;
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
}
