package org.armgals.examples.sim;

import java.time.Duration;
import java.util.List;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;

/**
 * A test example: tripods on the ground ({@code --atoms} of them, one by default) whose legs swing
 * to a scripted pattern, and a scripted "meta level" that tells the journal one adaptation at cycle
 * {@link #ADAPTATION_CYCLE}. Its crew reports {@link #MISSED} missed cycles and one figure.
 */
public final class ScriptedExample implements SimExample {
  /** The cycle at whose start the crew tells its adaptation. */
  public static final long ADAPTATION_CYCLE = 5;

  /** The missed cycles the crew reports. */
  public static final long MISSED = 2;

  private final String name;
  private final boolean usesBroker;

  /** An example called {@code scripted}, without a broker. */
  public ScriptedExample() {
    this("scripted", false);
  }

  /** An example of that name that uses a broker, or not. */
  public ScriptedExample(String name, boolean usesBroker) {
    this.name = name;
    this.usesBroker = usesBroker;
  }

  @Override
  public String name() {
    return name;
  }

  @Override
  public String summary() {
    return "tripods swinging their legs to a script";
  }

  @Override
  public Scene scene(RunSettings settings) {
    int atoms = settings.atoms().orElse(1);
    if (atoms > 4) {
      throw new IllegalArgumentException("--atoms " + atoms + " is too many: at most 4");
    }
    return Scenes.grid(atoms, 0.4);
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofMillis(250);
  }

  @Override
  public boolean usesBroker() {
    return usesBroker;
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    for (int id : sim.atomIds()) {
      sim.setController(
          id,
          (body, cycle) -> {
            double swing = 0.4 * Math.sin(cycle * 0.3 + id);
            body.command(Atom.target(Leg.PX), LegAngles.swing(swing, -Math.PI / 2));
            body.command(Atom.target(Leg.PY), LegAngles.swing(-swing, 0));
            if (cycle == ADAPTATION_CYCLE && id == sim.atomIds().get(0)) {
              journal.adaptation(id, "switched gait", "scripted at cycle " + cycle);
              journal.note(id, "a note");
            }
          });
    }
    return new Crew() {
      @Override
      public List<Summary.Entry> figures() {
        return List.of(new Summary.Entry("gait", "scripted"));
      }

      @Override
      public long missedCycles() {
        return MISSED;
      }
    };
  }
}
