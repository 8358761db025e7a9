package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import java.util.Locale;
import org.armgals.examples.cli.RunSettings;
import org.armgals.examples.cli.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.SimExample;
import org.armgals.maam.CycleReport;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.jspecify.annotations.Nullable;

/**
 * {@code walker}: one atom, resting as a tripod on its −x, −y and −z tips, shuffles across the
 * ground under reactive control (paper §5): a gait schema circles its three ground legs' tips a
 * third of a turn apart, waiting for legs that lag behind, which shuffles the atom towards −x
 * ({@link WalkerTuning#HEADING}); a balance schema suppresses the gait while the atom tips too far
 * (subsumption, figure 5). A watcher on the behavioral meta level notes each time the balance
 * reflex takes over, and sums the progress along the heading. One atom, a fixed shape: {@code
 * --atoms} does not apply.
 */
public final class Walker implements SimExample {

  @Override
  public String name() {
    return "walker";
  }

  @Override
  public String summary() {
    return "one atom shuffles on its three ground legs; a balance reflex suppresses the gait when"
        + " it tips";
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofSeconds(10);
  }

  /**
   * One atom standing as a tripod at the origin.
   *
   * @throws IllegalArgumentException if the settings give {@code --atoms}
   */
  @Override
  public Scene scene(RunSettings settings) {
    requireNonNull(settings, "settings");
    if (settings.atoms().isPresent()) {
      throw new IllegalArgumentException(
          "--atoms "
              + settings.atoms().get()
              + ": 'walker' is one atom; try 'caterpillar --atoms n' for a chain");
    }
    return Scenes.parse("scene walker\natom 1 0 0 0.07 tripod\n");
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    int id = sim.atomIds().get(0);
    WalkerRobot robot =
        new WalkerRobot(TrackedBody.of(sim, id), sim::timeNanos, settings.period().toNanos() / 1e9);
    BalanceWatch watch = new BalanceWatch(journal, id);
    robot.watchedBy((report, requests) -> watch.integrate(report));
    sim.setController(id, (atom, cycle) -> robot.cycle());
    return new Crew() {
      @Override
      public List<Summary.Entry> figures() {
        return List.of(
            new Summary.Entry("balance reflex", watch.takeovers() + " takeovers of the gait"),
            new Summary.Entry(
                "progress along the heading",
                String.format(Locale.ROOT, "%.3f m", watch.progress())),
            new Summary.Entry("module errors", Long.toString(robot.errors())));
      }
    };
  }

  /** Counts the times the balance reflex took over from the gait, and notes each in the trace. */
  private static final class BalanceWatch {
    private final Journal journal;
    private final int atom;
    private boolean balancing;
    private int takeovers;
    private WalkerSignals.@Nullable Course first;
    private WalkerSignals.@Nullable Course last;

    BalanceWatch(Journal journal, int atom) {
      this.journal = journal;
      this.atom = atom;
    }

    void integrate(CycleReport report) {
      for (CycleReport.Emission e : report.emissions()) {
        if (e.signal() instanceof WalkerSignals.Course course) {
          if (first == null) {
            first = course;
          }
          last = course;
        }
      }
      boolean now =
          report.emissions().stream()
              .anyMatch(
                  e ->
                      e.port().module().equals("balance")
                          && e.port().port().equals(WalkerSignals.TARGETS));
      if (now && !balancing) {
        takeovers++;
        journal.note(
            atom, String.format(Locale.ROOT, "balance reflex suppresses the gait (%d)", takeovers));
      }
      balancing = now;
    }

    /** Metres made good along {@link WalkerTuning#HEADING} since the first cycle. */
    double progress() {
      WalkerSignals.Course from = first;
      WalkerSignals.Course to = last;
      if (from == null || to == null) {
        return 0;
      }
      return (to.x() - from.x()) * Math.cos(WalkerTuning.HEADING)
          + (to.y() - from.y()) * Math.sin(WalkerTuning.HEADING);
    }

    int takeovers() {
      return takeovers;
    }
  }
}
