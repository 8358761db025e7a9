package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.JmsTransport;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.LoopRecord;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.ModelView;
import org.armgals.kernel.StructuralMeta;
import org.armgals.representation.p.PState;

/**
 * {@link Distributed}'s meta level in the world's JVM: a kernel of the world's runtime, the
 * crawlers' kind defined there as in the atoms' JVMs ({@link DistributedCrawler#kind}), and the
 * meta-entity {@link DistributedMeta}, which takes each atom's robot by name through the broker's
 * name service ({@link Kernel#lookupRemote}) with its filter of threshold meta-events. The world's
 * JVM is apart from every atom's: the meta is always remote to the robots.
 *
 * <p>In the world's lock step, {@link #keepUp} holds the world before it sends the readings of a
 * cycle until the meta has handled every notification an atom sent on the readings before (its
 * commands say up to which number) and the atom has acknowledged every request; {@link #journal}
 * then tells each request in the cycle from which it applies, with its acknowledgement, so that two
 * runs leave the same trace.
 *
 * <p>Threading: made and used on the simulation's thread; its listener runs on the kernel's.
 */
final class DistributedMetaLevel implements AutoCloseable {
  /** How often a wait for the meta looks again. */
  private static final long POLL_NANOS = 200_000;

  private final TimeSource time;
  private final Kernel kernel;
  private final DistributedMeta meta;
  private final StructuralMeta<PState> kind;
  private final LoopRecord loop;
  private final Map<Integer, Entity> robots = new LinkedHashMap<>();
  private final Map<String, Integer> atoms = new LinkedHashMap<>();
  private final Set<String> journaled = new HashSet<>();
  private final Map<String, ModelView> answered = new LinkedHashMap<>();
  private long gaveUp;

  private DistributedMetaLevel(
      ActiveRuntime runtime, long periodNanos, TimeSource time, LoopRecord loop) {
    this.time = time;
    this.loop = loop.watchMeta(DistributedMeta.NAME);
    this.kernel =
        org.armgals.kernel.StructuralMeta.bootstrap(
            runtime, KernelOptions.defaults().withJmx(true).withListener(loop));
    try {
      this.kind = DistributedCrawler.kind(kernel);
      this.meta = new DistributedMeta(periodNanos);
      meta.start(kernel);
    } catch (RuntimeException | Error e) {
      kernel.close();
      throw e;
    }
  }

  /**
   * The meta level of a run whose world's runtime is {@code runtime} (its transport allows the
   * kernel's events) and whose control period is {@code periodNanos}; {@code loop} records the
   * meta's side of the reflective loop.
   */
  static DistributedMetaLevel open(
      ActiveRuntime runtime, long periodNanos, TimeSource time, LoopRecord loop) {
    requireNonNull(runtime, "runtime");
    requireNonNull(time, "time");
    requireNonNull(loop, "loop");
    return new DistributedMetaLevel(runtime, periodNanos, time, loop);
  }

  /**
   * Takes the robot of atom {@code atom}, registered by its runtime under its name in the name
   * service of {@code names}, with the filter {@value DistributedMeta#THRESHOLDS_ONLY}, and waits
   * until the meta has heard from it (the complete state it sends when taken): from then on it
   * hears every notification the robot sends.
   *
   * @throws IllegalStateException no answer within {@code timeout}, or the atom's process ended
   *     first, naming the robot
   */
  void take(int atom, JmsTransport names, Duration timeout, BooleanSupplier ended) {
    String name = DistributedCrawler.robotName(atom);
    loop.watch(name);
    Entity robot = kernel.lookupRemote(names, name, kind);
    meta.addBaseLevelEntity(robot).touch();
    meta.setFilter(robot, DistributedMeta.THRESHOLDS_ONLY).touch();
    robots.put(atom, robot);
    atoms.put(name, atom);
    long deadline = time.nanoTime() + timeout.toNanos();
    while (meta.model(robot).getValue().lastSeq() < 1) {
      if (ended.getAsBoolean() || time.nanoTime() > deadline) {
        throw new IllegalStateException(
            "the meta level took robot "
                + name
                + " but never heard from it"
                + (ended.getAsBoolean() ? ": its JVM ended" : " within " + timeout));
      }
      LockSupport.parkNanos(POLL_NANOS);
    }
  }

  /**
   * Waits until the meta has handled every notification of atom {@code atom}'s robot up to number
   * {@code notified} and the robot has acknowledged every request the meta sent it, at most until
   * {@code deadlineNanos} (on this level's time) or until {@code ended} says the atom's process
   * ended.
   *
   * @return whether it caught up; a wait that gave up is counted ({@link #figures})
   */
  boolean keepUp(int atom, long notified, long deadlineNanos, BooleanSupplier ended) {
    Entity robot = requireNonNull(robots.get(atom), () -> "atom " + atom + " was not taken");
    while (true) {
      ModelView view = meta.model(robot).getValue();
      if (view.lastSeq() >= notified && acknowledged(view)) {
        return true;
      }
      if (ended.getAsBoolean()) {
        return false;
      }
      if (time.nanoTime() > deadlineNanos) {
        gaveUp++;
        return false;
      }
      LockSupport.parkNanos(POLL_NANOS);
    }
  }

  /** Every request sent acknowledged: the meta sends a robot one at most. */
  private static boolean acknowledged(ModelView view) {
    return view.appliedVersion() >= view.requestedVersion() || view.refusedAdaptations() > 0;
  }

  /**
   * Tells {@code journal}, at world time {@code nowNanos}, each request of the meta that applies
   * from then or before and whose acknowledgement has come, once: an adaptation if the robot
   * applied it, a note if it refused it. In lock step that is the cycle the request names, in every
   * run.
   */
  void journal(long nowNanos, Journal journal) {
    for (DistributedMeta.Decision d : meta.decisions()) {
      if (journaled.contains(d.robot()) || d.fromNanos() > nowNanos) {
        continue;
      }
      ModelView view = meta.model(robots.get(atoms.get(d.robot()))).getValue();
      boolean applied = view.appliedVersion() >= d.version();
      if (!applied && view.refusedAdaptations() == 0) {
        continue; // not acknowledged yet
      }
      journaled.add(d.robot());
      answered.put(d.robot(), view);
      int atom = atoms.get(d.robot());
      if (applied) {
        journal.adaptation(
            atom,
            String.format(
                Locale.ROOT,
                "stroke %.2f → %.2f rad from %.2f s (changeModule %s, request %d, acknowledged"
                    + " applied)",
                DistributedGait.SWING,
                d.swing(),
                d.fromNanos() / 1e9,
                DistributedCrawler.GAIT,
                d.version()),
            d.reason());
      } else {
        journal.note(
            atom,
            "refused changeModule "
                + DistributedCrawler.GAIT
                + " (request "
                + d.version()
                + "): "
                + view.lastRefusal()
                + "; it keeps its stroke");
      }
    }
  }

  /** What the meta asked of atom {@code atom}'s robot, if anything. */
  Optional<DistributedMeta.Decision> decision(int atom) {
    return meta.decision(DistributedCrawler.robotName(atom));
  }

  /** Whether atom {@code atom}'s robot acknowledged the meta's request as applied. */
  boolean applied(int atom) {
    ModelView view = answered.get(DistributedCrawler.robotName(atom));
    return view != null
        && decision(atom).map(d -> view.appliedVersion() >= d.version()).orElse(false);
  }

  /** The meta's model of atom {@code atom}'s robot now. */
  ModelView model(int atom) {
    return meta.model(requireNonNull(robots.get(atom), () -> "atom " + atom)).getValue();
  }

  /** The robots the meta took, by name, in the chain's order. */
  List<String> robots() {
    return List.copyOf(atoms.keySet());
  }

  /** The names of the entities the meta is the behavioral meta of, as its kernel says. */
  List<String> baseLevelEntities() {
    return meta.baseLevelEntities().stream().map(Entity::name).toList();
  }

  /**
   * The summary's figures of this meta level, beside the loop's ({@link LoopRecord#finish}): where
   * it runs and what it takes, what it asked of each robot, and how the world waited for it.
   *
   * @param lockStep whether the world waited for the meta
   * @param patience how long a wait for it lasted at most
   */
  List<Summary.Entry> figures(boolean lockStep, Duration patience) {
    List<Summary.Entry> figures = new ArrayList<>();
    figures.add(
        new Summary.Entry(
            "meta-entity",
            DistributedMeta.NAME
                + " takes "
                + String.join(", ", atoms.keySet())
                + " by name through the broker; filter \""
                + DistributedMeta.THRESHOLDS_ONLY
                + "\""));
    figures.add(
        new Summary.Entry(
            "world waits for its meta",
            lockStep
                ? String.format(
                    Locale.ROOT,
                    "before each cycle's readings, until it has handled the notifications of the"
                        + " cycle before and every request is acknowledged (up to %d ms); %d waits"
                        + " gave up",
                    patience.toMillis(),
                    gaveUp)
                : "never (paced to real time): a request applies when it arrives"));
    return figures;
  }

  @Override
  public void close() {
    kernel.close();
  }
}
