package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
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
import org.armgals.kernel.Kernel;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.LegBinding;
import org.armgals.representation.p.PState;

/**
 * {@code caterpillar}: a chain of atoms bound leg to leg along x crawls forward with a wave gait,
 * the paper's modular robot (§1, §5.4). Every atom runs the same robot program, a {@link
 * CaterpillarSegment}; the head beats the rhythm and each segment passes it to the one behind
 * through their bound legs (neighbour messages), a quarter step later, so a wave runs down the
 * chain. Each segment is a kernel entity of the kind {@code CaterpillarSegment} on an island of its
 * own (paper figure 8). The head's behavioral meta-entity, {@code bmrobot<head>} with the policy
 * {@link CaterpillarMeta}, is notified of the head's state every cycle on its own object, watches
 * the progress of each step and lengthens the stride while it is too short, through the head, whose
 * rhythm carries the new stride down the chain. It runs in lock step with the head, one cycle
 * behind: a change decided on cycle {@code n} is applied at the beginning of cycle {@code n + 1},
 * so runs are reproducible. Each change is told to the journal when the head applies it.
 *
 * <p>{@code --atoms n}: the chain's length, 2 to 8 (default 4).
 */
public final class Caterpillar implements SimExample {

  /** The chain's length when the settings do not give one. */
  public static final int DEFAULT_ATOMS = 4;

  /** The shortest chain. */
  public static final int MIN_ATOMS = 2;

  /** The longest chain. */
  public static final int MAX_ATOMS = 8;

  private static final double SPACING = 0.22;

  private final boolean metaLevel;

  /** The caterpillar with its meta level. */
  public Caterpillar() {
    this(true);
  }

  private Caterpillar(boolean metaLevel) {
    this.metaLevel = metaLevel;
  }

  /**
   * The same robots without a meta level, the head notifying no one: what notifying costs is the
   * difference (benchmarks/reflect.sh). Named {@code caterpillar-without-meta}; not in the catalog.
   */
  public static Caterpillar withoutMetaLevel() {
    return new Caterpillar(false);
  }

  @Override
  public String name() {
    return metaLevel ? "caterpillar" : "caterpillar-without-meta";
  }

  @Override
  public String summary() {
    return "a chain of atoms crawls with a wave passed leg to leg; its meta level lengthens the"
        + " stride";
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofSeconds(10);
  }

  /**
   * A chain of {@code --atoms} atoms (default 4) along x, bound {@code i:+x} to {@code i+1:-x}; the
   * head is the last, at the largest x.
   *
   * @throws IllegalArgumentException if {@code --atoms} is not between 2 and 8
   */
  @Override
  public Scene scene(RunSettings settings) {
    requireNonNull(settings, "settings");
    int n = atoms(settings);
    StringBuilder text = new StringBuilder("scene caterpillar").append(n).append('\n');
    for (int id = 1; id <= n; id++) {
      text.append(
          String.format(
              Locale.ROOT,
              "atom %d %.2f 0 %.3f 1 0 0 %.0f%n",
              id,
              (id - 1) * SPACING,
              CaterpillarTuning.HEIGHT,
              CaterpillarTuning.ROLL_DEGREES));
    }
    for (int id = 1; id < n; id++) {
      text.append(String.format(Locale.ROOT, "bond %d:+x %d:-x%n", id, id + 1));
    }
    return Scenes.parse(text.toString());
  }

  /**
   * The head's meta level: {@code bmrobot<head>} ({@link CaterpillarMeta}) watches the head's
   * states; every segment is of the kind {@code CaterpillarSegment}.
   */
  @Override
  public Optional<MetaLevel> metaLevel(RunSettings settings) {
    return metaLevel ? Optional.of(new Level(atoms(settings))) : Optional.empty();
  }

  /** The caterpillar's meta level: the same code in the robots' JVM or another. */
  static final class Level implements MetaLevel {
    private final int atoms;
    private final CaterpillarMeta meta;

    Level(int atoms) {
      this.atoms = atoms;
      this.meta = new CaterpillarMeta("bmrobot" + atoms);
    }

    @Override
    public Map<String, StructuralMeta<PState>> kinds(Kernel kernel) {
      StructuralMeta<PState> kind = CaterpillarSegment.kind(kernel);
      Map<String, StructuralMeta<PState>> kinds = new LinkedHashMap<>();
      for (int id = 1; id <= atoms; id++) {
        kinds.put("segment" + id, kind);
      }
      return kinds;
    }

    @Override
    public List<Watch> watches(MetaNotes notes) {
      return List.of(new Watch(meta, List.of("segment" + atoms), ""));
    }

    @Override
    public List<Summary.Entry> figures() {
      return List.of(
          new Summary.Entry(
              "stride", String.format(Locale.ROOT, "%.2f rad at the end", meta.stride())),
          new Summary.Entry("steps judged by the meta level", Integer.toString(meta.steps())));
    }
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    List<Integer> ids = sim.atomIds();
    double cycleSeconds = settings.period().toNanos() / 1e9;
    int head = ids.get(ids.size() - 1);
    Reflection reflection =
        Reflection.open(sim, settings, name(), metaLevel(settings).orElse(null), journal);
    try {
      List<CaterpillarSegment> segments = new ArrayList<>();
      for (int i = 0; i < ids.size(); i++) {
        int id = ids.get(i);
        TrackedBody body = TrackedBody.of(sim, id);
        CaterpillarSegment segment =
            new CaterpillarSegment(
                "segment" + id, body, sim::timeNanos, ids.size() - 1 - i, cycleSeconds);
        Island island = reflection.island("segment" + id, AdaptationPoint.BEGIN_OF_CYCLE);
        reflection.start(
            segment,
            id,
            island,
            id == head && metaLevel ? NotificationPolicy.statesOnly() : NotificationPolicy.quiet());
        sim.setController(id, body.driving(() -> reflection.step(island)));
        segments.add(segment);
      }
      reflection.ready();
      return new CaterpillarCrew(sim, segments, reflection);
    } catch (RuntimeException | Error e) {
      reflection.close();
      throw e;
    }
  }

  static int atoms(RunSettings settings) {
    int n = settings.atoms().orElse(DEFAULT_ATOMS);
    if (n < MIN_ATOMS || n > MAX_ATOMS) {
      throw new IllegalArgumentException(
          "--atoms "
              + n
              + ": a caterpillar has between "
              + MIN_ATOMS
              + " and "
              + MAX_ATOMS
              + " atoms");
    }
    return n;
  }

  /** The segments and the reflective side of one run. */
  private record CaterpillarCrew(Simulation sim, List<CaterpillarSegment> segments, Reflection loop)
      implements Crew {

    @Override
    public Optional<Reflection> reflection() {
      return Optional.of(loop);
    }

    @Override
    public List<Summary.Entry> figures() {
      int bonds = 0;
      for (int id : sim.atomIds()) {
        if (sim.body(id).read(Atom.binding(CaterpillarModules.FRONT)) instanceof LegBinding.Bound) {
          bonds++;
        }
      }
      long errors = segments.stream().mapToLong(CaterpillarSegment::errors).sum();
      return List.of(
          new Summary.Entry("bonds held", bonds + " of " + (sim.atomIds().size() - 1)),
          new Summary.Entry("module errors", Long.toString(errors)));
    }
  }
}
