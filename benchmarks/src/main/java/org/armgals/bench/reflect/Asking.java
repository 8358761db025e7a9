package org.armgals.bench.reflect;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.MetaLevel;
import org.armgals.examples.sim.Reflection;
import org.armgals.examples.sim.SimExample;
import org.armgals.gals.Island;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;

/**
 * {@code reflect-asking}: the benchmark's example of a busy reflective loop. One standing atom
 * whose robot ({@link AskingRobot}) notifies its state every cycle to a meta level ({@link
 * AskingMeta}) that asks for a change every {@value #EVERY} cycles, so that a run makes hundreds of
 * requests, each timed from the notification it was decided on to its being applied (the run's
 * summary, line "notified to applied"). A {@link SimExample} service of the benchmarks' jar, so
 * that a meta level in another JVM ({@code --meta remote}) finds it too; run with {@link #run}, as
 * {@code armgals run} runs the examples of its catalog.
 */
public final class Asking implements SimExample {
  /** The example's name. */
  public static final String NAME = "reflect-asking";

  /** The meta asks for a change every this many cycles. */
  static final int EVERY = 5;

  private static final int ATOM = 1;

  @Override
  public String name() {
    return NAME;
  }

  @Override
  public String summary() {
    return "a robot whose meta level asks for a change every " + EVERY + " cycles (a benchmark)";
  }

  @Override
  public Scene scene(RunSettings settings) {
    requireNonNull(settings, "settings");
    if (settings.atoms().isPresent()) {
      throw new IllegalArgumentException(
          "'" + NAME + "' is one atom: --atoms does not apply (leave it out)");
    }
    return Scenes.parse("scene asking\natom " + ATOM + " 0 0 0.07 tripod\n");
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofSeconds(30);
  }

  @Override
  public Optional<MetaLevel> metaLevel(RunSettings settings) {
    long period = settings.period().toNanos();
    return Optional.of(
        new MetaLevel() {
          @Override
          public Map<String, StructuralMeta<PState>> kinds(Kernel kernel) {
            return Map.of(AskingRobot.NAME, AskingRobot.kind(kernel));
          }

          @Override
          public List<Watch> watches(MetaNotes notes) {
            return List.of(new Watch(new AskingMeta(period, EVERY), List.of(AskingRobot.NAME), ""));
          }
        });
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    Reflection reflection =
        Reflection.open(sim, settings, NAME, metaLevel(settings).orElseThrow(), journal);
    try {
      Body body = sim.body(ATOM);
      AskingRobot robot = new AskingRobot(body, sim::timeNanos);
      Island island = reflection.island(AskingRobot.NAME, AdaptationPoint.BEGIN_OF_CYCLE);
      reflection.start(robot, ATOM, island, NotificationPolicy.statesOnly());
      sim.setController(ATOM, Controller.driving(body, () -> reflection.step(island)));
      reflection.ready();
      return new Crew() {
        @Override
        public Optional<Reflection> reflection() {
          return Optional.of(reflection);
        }
      };
    } catch (RuntimeException | Error e) {
      reflection.close();
      throw e;
    }
  }
}
