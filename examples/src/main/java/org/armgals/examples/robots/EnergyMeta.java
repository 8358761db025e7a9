package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import org.armgals.active.Filter;
import org.armgals.examples.robots.EnergyModules.Stepper;
import org.armgals.examples.robots.EnergySignals.EnergyLevel;
import org.armgals.examples.robots.EnergySignals.EnergyThreshold;
import org.armgals.examples.sim.Journal;
import org.armgals.maam.Adaptation;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.CycleReport;
import org.armgals.maam.Signal;

/**
 * The behavioral meta level of the {@link EnergySaver}: the paper's battery example (§2.3, §4). It
 * judges the robot's energy events and threshold meta-events with a filter, a JMS selector
 * evaluated by arm-active's {@link Filter} as the kernel's metas do. While the battery is above the
 * threshold its filter takes threshold meta-events only, so it drops every energy event (counted);
 * on the meta-event that the battery fell under the threshold it swaps its filter to take energy
 * events too, and asks the robot to change its stepper for one of the saving gait ({@code
 * changeModule}), once. From the energy events it then takes, it models the draw of the new gait.
 *
 * <p>Threading: called on the robot's thread at the end of each cycle (a {@link BMetaRobot}).
 */
final class EnergyMeta implements BMetaRobot {
  static final String THRESHOLDS_ONLY = "kind = 'threshold'";
  static final String FOLLOWING_ENERGY = "kind = 'threshold' OR kind = 'energy'";

  /** How long the meta watches the saving gait's draw before telling it. */
  private static final double WATCH_SECONDS = 1.0;

  private final int atom;
  private final Journal journal;
  private final double periodSeconds;
  private Filter filter = Filter.selector(THRESHOLDS_ONLY);
  private long dropped;
  private long followed;
  private int switches;
  private double followedSince = Double.NaN;
  private double joulesWhenSwitched;
  private double savingWatts = Double.NaN;

  EnergyMeta(int atom, Journal journal, double periodSeconds) {
    this.atom = atom;
    this.journal = requireNonNull(journal, "journal");
    this.periodSeconds = periodSeconds;
  }

  @Override
  public void onCycle(CycleReport report, Consumer<Adaptation> requests) {
    double now = report.nanoTime() / 1e9;
    for (CycleReport.Emission emission : report.emissions()) {
      Signal signal = emission.signal();
      Map<String, Object> properties =
          switch (signal) {
            case EnergyLevel level -> level.properties();
            case EnergyThreshold threshold -> threshold.properties();
            default -> Map.of();
          };
      if (properties.isEmpty()) {
        continue;
      }
      if (!filter.matches(properties)) {
        dropped++;
        continue;
      }
      switch (signal) {
        case EnergyThreshold t when t.below() && switches == 0 -> switchToSaving(t, now, requests);
        case EnergyLevel level -> follow(level, now);
        default -> {}
      }
    }
  }

  private void switchToSaving(EnergyThreshold t, double now, Consumer<Adaptation> requests) {
    filter = Filter.selector(FOLLOWING_ENERGY);
    journal.note(
        atom,
        "meta level: threshold meta-event '"
            + t.name()
            + "', filter now \""
            + FOLLOWING_ENERGY
            + "\" after dropping "
            + dropped
            + " energy events");
    EnergyGait saving = EnergyGait.SAVING;
    requests.accept(
        new Adaptation.ChangeModule(new Stepper(EnergyRobot.STEPPER, saving, periodSeconds)));
    switches++;
    followedSince = now;
    journal.adaptation(
        atom,
        String.format(
            Locale.ROOT,
            "switched to saving gait (stroke %.2f rad, %.1f Hz, torque limit %.2f N·m)",
            saving.stroke(),
            saving.frequency(),
            saving.torqueLimit()),
        String.format(Locale.ROOT, "battery at %.0f%%", 100 * t.fraction()));
  }

  private void follow(EnergyLevel level, double now) {
    followed++;
    if (followed == 1) {
      joulesWhenSwitched = level.joules();
    } else if (Double.isNaN(savingWatts) && now - followedSince >= WATCH_SECONDS) {
      savingWatts = (joulesWhenSwitched - level.joules()) / (now - followedSince);
      journal.note(
          atom,
          String.format(
              Locale.ROOT,
              "meta level: the saving gait draws %.2f W, %.2f J left: about %.0f s more",
              savingWatts,
              level.joules(),
              savingWatts > 0 ? level.joules() / savingWatts : Double.POSITIVE_INFINITY));
    }
  }

  /** Energy events the filter dropped (all of them while the battery was above the threshold). */
  long dropped() {
    return dropped;
  }

  /** Energy events the filter let through, after the threshold meta-event. */
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
  Filter filter() {
    return filter;
  }
}
