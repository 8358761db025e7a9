package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.Locale;
import java.util.Map;
import org.armgals.examples.sim.MetaLevel;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Notification;
import org.armgals.kernel.StateEvent;
import org.armgals.kernel.ThresholdEvent;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;

/**
 * The behavioral meta level of the {@link EnergySaver}: the paper's battery example (§2.3, §4), a
 * behavioral meta-entity of the kernel. Its robot notifies its state every cycle and the threshold
 * meta-events of its battery ({@link EnergySaver#LOW}, watched by the kernel on the robot's
 * observed fraction). While the battery is above the threshold this meta's filter, a JMS selector,
 * takes threshold meta-events only ({@value #THRESHOLDS_ONLY}): every state event is dropped. On
 * the meta-event that the battery fell under the threshold it changes its filter to take the states
 * too ({@value #FOLLOWING_ENERGY}) and asks the robot for the stepper of the saving gait ({@code
 * changeModule}), once; from the states it then takes, it measures the draw of the new gait.
 *
 * <p>Threading: runs on its meta-entity's own object, never on the robot's thread, in the robot's
 * JVM or another. Its figures are read once the run is over.
 */
final class EnergyMeta extends BMetaRobot {
  static final String THRESHOLDS_ONLY = "kind = 'threshold'";
  static final String FOLLOWING_ENERGY = "kind = 'threshold' OR kind = 'state'";

  /** How long the meta watches the saving gait's draw before telling it. */
  private static final double WATCH_SECONDS = 1.0;

  private final MetaLevel.MetaNotes notes;
  private volatile String filter = THRESHOLDS_ONLY;
  private volatile long followed;
  private volatile int switches;
  private double followedSince = Double.NaN;
  private double joulesWhenSwitched;
  private volatile double savingWatts = Double.NaN;

  EnergyMeta(MetaLevel.MetaNotes notes) {
    super("bmenergy", Damping.none());
    this.notes = requireNonNull(notes, "notes");
  }

  @Override
  public void onNotification(MetaContext context, Notification n) {
    switch (n) {
      case ThresholdEvent t when t.below() && switches == 0 -> switchToSaving(context, t);
      case StateEvent s when switches > 0 -> follow(context, s);
      default -> {}
    }
  }

  private void switchToSaving(MetaContext context, ThresholdEvent t) {
    context.setFilter(t.entity(), FOLLOWING_ENERGY);
    filter = FOLLOWING_ENERGY;
    String robot = context.entity(t.entity()).name();
    notes.note(
        robot,
        context.nanoTime(),
        "threshold meta-event '" + t.threshold() + "': filter now \"" + FOLLOWING_ENERGY + "\"");
    EnergyGait saving = EnergyGait.SAVING;
    String why =
        String.format(
            Locale.ROOT,
            "battery at %.0f%%: saving gait (stroke %.2f rad, %.1f Hz, torque limit %.2f N·m)",
            100 * t.value(),
            saving.stroke(),
            saving.frequency(),
            saving.torqueLimit());
    var request =
        RobotKind.because(
            why,
            RobotKind.changeModule(EnergyRobot.STEPPER, Map.of(EnergyRobot.GAIT, saving.name())));
    if (context.adapt(t.entity(), request).isPresent()) {
      switches++;
      followedSince = context.nanoTime() / 1e9;
    }
  }

  private void follow(MetaContext context, StateEvent s) {
    if (!(s.observation().get(EnergyRobot.JOULES) instanceof Double joules)) {
      return;
    }
    double now = context.nanoTime() / 1e9;
    followed++;
    if (followed == 1) {
      joulesWhenSwitched = joules;
    } else if (Double.isNaN(savingWatts) && now - followedSince >= WATCH_SECONDS) {
      savingWatts = (joulesWhenSwitched - joules) / (now - followedSince);
      notes.note(
          context.entity(s.entity()).name(),
          context.nanoTime(),
          String.format(
              Locale.ROOT,
              "the saving gait draws %.2f W, %.2f J left: about %.0f s more",
              savingWatts,
              joules,
              savingWatts > 0 ? joules / savingWatts : Double.POSITIVE_INFINITY));
    }
  }

  /** States the filter let through, after the threshold. */
  long followed() {
    return followed;
  }

  /** Gait switches asked for. */
  int switches() {
    return switches;
  }

  /** The saving gait's draw as the meta measured it, W; NaN until measured. */
  double savingWatts() {
    return savingWatts;
  }

  /** The filter now. */
  String filter() {
    return filter;
  }
}
