package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.MetaLevel;
import org.armgals.examples.sim.Reflection;
import org.armgals.examples.sim.SimExample;
import org.armgals.gals.Island;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.Notification;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * {@code walker}: one atom, resting as a tripod on its −x, −y and −z tips, shuffles across the
 * ground under reactive control (paper §5): a gait schema circles its three ground legs' tips a
 * third of a turn apart, waiting for legs that lag behind, which shuffles the atom towards −x
 * ({@link WalkerTuning#HEADING}); a balance schema suppresses the gait while the atom tips too far
 * (subsumption, figure 5). The robot is a kernel entity; a watcher on its behavioral meta level
 * notes each time the balance reflex takes over, and sums the progress along the heading. One atom,
 * a fixed shape: {@code --atoms} does not apply.
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

  /**
   * Its meta level: a watcher of the walker's balance reflex and course, which asks for nothing.
   */
  @Override
  public Optional<MetaLevel> metaLevel(RunSettings settings) {
    return Optional.of(new Level());
  }

  /** The walker's meta level: the same code in the robot's JVM or another. */
  static final class Level implements MetaLevel {
    private @Nullable BalanceWatch watch;

    @Override
    public Map<String, StructuralMeta<PState>> kinds(Kernel kernel) {
      return Map.of(ROBOT, WalkerRobot.kind(kernel));
    }

    @Override
    public List<Watch> watches(MetaNotes notes) {
      BalanceWatch w = new BalanceWatch(notes);
      watch = w;
      return List.of(new Watch(w, List.of(ROBOT), ""));
    }

    @Override
    public List<Summary.Entry> figures() {
      BalanceWatch w = requireNonNull(watch, "watch");
      return List.of(
          new Summary.Entry("balance reflex", w.takeovers() + " takeovers of the gait"),
          new Summary.Entry(
              "progress along the heading", String.format(Locale.ROOT, "%.3f m", w.progress())));
    }
  }

  private static final String ROBOT = "walker";

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    int id = sim.atomIds().get(0);
    TrackedBody body = TrackedBody.of(sim, id);
    WalkerRobot robot = new WalkerRobot(body, sim::timeNanos, settings.period().toNanos() / 1e9);
    Reflection reflection =
        Reflection.open(sim, settings, name(), metaLevel(settings).orElseThrow(), journal);
    try {
      Island island = reflection.island(ROBOT, AdaptationPoint.END_OF_CYCLE);
      reflection.start(robot, id, island, NotificationPolicy.statesOnly());
      sim.setController(id, body.driving(() -> reflection.step(island)));
      reflection.ready();
    } catch (RuntimeException | Error e) {
      reflection.close();
      throw e;
    }
    return new Crew() {
      @Override
      public Optional<Reflection> reflection() {
        return Optional.of(reflection);
      }

      @Override
      public List<Summary.Entry> figures() {
        return List.of(new Summary.Entry("module errors", Long.toString(robot.errors())));
      }
    };
  }

  /**
   * The walker's behavioral meta level: from the walker's states it counts the times the balance
   * reflex took over from the gait, noting each, and sums the progress along the heading. It only
   * watches.
   */
  private static final class BalanceWatch extends BMetaRobot {
    private final MetaLevel.MetaNotes notes;
    private boolean balancing;
    private volatile int takeovers;
    private double firstX = Double.NaN;
    private double firstY;
    private volatile double progress;

    BalanceWatch(MetaLevel.MetaNotes notes) {
      super("bmwalker", Damping.none());
      this.notes = notes;
    }

    @Override
    public void onNotification(MetaContext context, Notification n) {
      Map<String, Object> seen = observation(n).orElse(null);
      if (seen == null || !(seen.get(WalkerRobot.BALANCING) instanceof Boolean now)) {
        return;
      }
      double x = (Double) seen.get(WalkerRobot.X);
      double y = (Double) seen.get(WalkerRobot.Y);
      if (Double.isNaN(firstX)) {
        firstX = x;
        firstY = y;
      }
      progress =
          (x - firstX) * Math.cos(WalkerTuning.HEADING)
              + (y - firstY) * Math.sin(WalkerTuning.HEADING);
      if (now && !balancing) {
        takeovers++;
        notes.note(
            ROBOT,
            context.nanoTime(),
            String.format(Locale.ROOT, "balance reflex suppresses the gait (%d)", takeovers));
      }
      balancing = now;
    }

    /** Metres made good along {@link WalkerTuning#HEADING} since the first cycle. */
    double progress() {
      return progress;
    }

    int takeovers() {
      return takeovers;
    }
  }
}
