package org.armgals.examples.sim;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import org.armgals.active.TimeSource;
import org.armgals.examples.run.RunInterrupted;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.SimulationBuilder;
import org.armgals.maam.sim.spi.Pacer;

/**
 * Runs a {@link SimExample} as {@code armgals run} does: builds its scene's simulation with the
 * settings' seed and period, lets its crew drive it for the settings' duration (as fast as
 * possible, or paced to real time), shows the progress, and leaves in the output directory:
 *
 * <ul>
 *   <li>{@value #TRACE}: the simulator's trace, whose header names the example and its options (so
 *       that {@code armgals replay} can run it again);
 *   <li>{@value Outputs#TRAJECTORY}, {@value Outputs#ENERGY}, {@value Outputs#ADAPTATIONS}: the
 *       atoms' paths seen from above over the scene, the energy left over time, the adaptations on
 *       a time line;
 *   <li>{@value Outputs#START} and {@value Outputs#END}: the molecule in its scene at the start and
 *       at the end, in one frame;
 *   <li>beside each picture, the same as SVG;
 *   <li>{@value #PROGRAMS}: the robots' schemas and schedules as they change, for {@code armgals
 *       view}.
 * </ul>
 *
 * It writes them into a {@link Staging} directory inside the output directory and moves them into
 * place when it ends, so that a run that fails leaves the previous run's files as they were. On
 * Ctrl-C ({@link Interruption}) it stops after the cycle it is in, keeps what it has, the trace
 * ending with a line that marks it incomplete ({@link Replay#incomplete}), and exits 130.
 *
 * <p>The summary: the displacement of the molecule's centre (on the ground plane, start to end in a
 * straight line) and the length of the path it went along, its speed in atom diameters per second
 * (an atom's diameter is tip to tip, legs straight), the energy used, the adaptations made and why,
 * and the missed cycles (paced to real time: cycles that ended later than a period after their time
 * on a schedule that starts with the first cycle, as the pacer's does, so that neither the crew's
 * own start (a meta level's JVM, say) nor a first cycle slowed by the JVM's warming up makes every
 * later cycle missed; plus those the crew reports).
 */
final class SimRun {
  static final String TRACE = "trace.jsonl";

  /** Trace header attributes: what a replay needs beyond the scene and the seed. */
  static final String EXAMPLE = "example";

  static final String CYCLES = "cycles";
  static final String PERIOD_NANOS = "periodNanos";
  static final String ATOMS = "atoms";

  /**
   * The leg model, {@code kinematic} or {@code jointed}; a trace without it was written before the
   * robots moved to kinematic legs (decision 0065), on jointed ones.
   */
  static final String LEGS = "legs";

  /**
   * Set to {@value #FREE} when the robots ran free of their meta level (paced to real time): a
   * replay then re-applies the requests where the loop's record says they were applied.
   */
  static final String PACING = "pacing";

  static final String FREE = "free";

  /**
   * The robots' programs, one JSON object a line: a robot's schemas and schedule at the first cycle
   * and after each cycle that changed them ({@code cycle}, {@code robot}, {@code schemas}, {@code
   * schedule}), for {@code armgals view}.
   */
  static final String PROGRAMS = "programs.jsonl";

  /** Where a warm-up's crew writes, inside the staging directory; gone before the run starts. */
  private static final String WARMUP = ".warmup";

  private SimRun() {}

  static Summary run(SimExample example, RunSettings settings, PrintStream out) {
    try (Interruption interruption = Interruption.onCtrlC()) {
      return run(
          example, settings, out, System.console() != null, TimeSource.system(), interruption);
    }
  }

  /**
   * The run as {@code armgals run --live} makes it: paced to real time times {@code speed}, telling
   * {@code watcher} what happens.
   */
  static Summary run(
      SimExample example, RunSettings settings, PrintStream out, RunWatcher watcher, double speed) {
    try (Interruption interruption = Interruption.onCtrlC()) {
      return run(
          example,
          settings,
          out,
          System.console() != null,
          TimeSource.system(),
          interruption,
          watcher,
          speed);
    }
  }

  static Summary run(
      SimExample example,
      RunSettings settings,
      PrintStream out,
      boolean terminal,
      TimeSource clock) {
    try (Interruption interruption = Interruption.manual()) {
      return run(example, settings, out, terminal, clock, interruption);
    }
  }

  /**
   * The run, writing into a new directory inside the output directory that it moves into place when
   * the run ends (completed or interrupted): a run that fails leaves the previous run's files as
   * they were. Interrupted, it stops after the cycle it is in, keeps the trace up to there with a
   * last line that marks it incomplete, draws its pictures, says so and throws {@link
   * RunInterrupted}.
   */
  static Summary run(
      SimExample example,
      RunSettings settings,
      PrintStream out,
      boolean terminal,
      TimeSource clock,
      Interruption interruption) {
    return run(example, settings, out, terminal, clock, interruption, RunWatcher.NONE, 1.0);
  }

  /** As above, telling {@code watcher} what happens, paced at {@code speed} if real time. */
  static Summary run(
      SimExample example,
      RunSettings settings,
      PrintStream out,
      boolean terminal,
      TimeSource clock,
      Interruption interruption,
      RunWatcher watcher,
      double speed) {
    checkBroker(example, settings);
    Scene scene = example.scene(settings);
    long cycles = cycles(example, settings);
    try (Staging staging = Staging.in(settings.out())) {
      RunSettings staged = settings.withOut(staging.dir());
      out.printf(
          Locale.ROOT,
          "armgals %s: scene '%s', %d atoms, %d cycles of %s ms, seed %d%s%s%s%n",
          example.name(),
          scene.name(),
          scene.atoms().size(),
          cycles,
          millis(settings.period()),
          settings.seed(),
          settings.legs() == RunSettings.DEFAULT_LEGS ? "" : ", " + legs(settings) + " legs",
          settings.realTime() ? ", paced to real time" : "",
          settings.realTime() && speed != 1.0
              ? String.format(
                  Locale.ROOT,
                  " times %s",
                  new java.math.BigDecimal(speed).stripTrailingZeros().toPlainString())
              : "");
      if (!settings.warmup().isZero()) {
        Duration took =
            warmUp(example, settings, staging.dir().resolve(WARMUP), clock, interruption);
        out.printf(
            Locale.ROOT,
            "warmed up: %.2f s simulated in %.2f s, in virtual time on a scratch copy of the world,"
                + " thrown away%n",
            settings.warmup().toNanos() / 1e9,
            took.toNanos() / 1e9);
      }
      Recording recording = new Recording(scene.params());
      Progress progress = new Progress(out, terminal, cycles, clock);
      long ran;
      long missed;
      long crewMissed;
      List<Summary.Entry> figures;
      Path tracePath = staging.dir().resolve(TRACE);
      try (Writer trace = Files.newBufferedWriter(tracePath, StandardCharsets.UTF_8)) {
        try (Simulation sim = build(example, staged, scene, cycles, trace, speed)) {
          RecordingJournal journal = new RecordingJournal(sim, recording);
          // The first sample is taken after cycle 0, of the readings at its start (t = 0): the
          // same readings as the trace's first line, with the scene's bonds made and its poses
          // applied.
          try (Crew crew = example.start(sim, staged, journal);
              Writer programs =
                  Files.newBufferedWriter(
                      staging.dir().resolve(PROGRAMS), StandardCharsets.UTF_8)) {
            watcher.started(
                LiveJson.start("live", example.name(), scene, cycles, settings.period(), speed));
            crew.reflection().ifPresent(r -> r.watch(watcher));
            Watching watching =
                new Watching(watcher, sim, scene, crew.reflection().orElse(null), programs);
            Lateness lateness = new Lateness(settings.period().toNanos());
            ran =
                drive(
                    sim,
                    cycles,
                    settings,
                    recording,
                    progress,
                    interruption,
                    watching,
                    speed,
                    lateness);
            watcher.ended(LiveJson.end(ran, cycles));
            missed = lateness.missed();
            recording.end(sim.timeNanos());
            crewMissed = crew.missedCycles();
            List<Summary.Entry> loop = new java.util.ArrayList<>();
            if (ran > 0) {
              loop.addAll(crew.finish(staging.dir()));
            }
            figures = new java.util.ArrayList<>();
            if (!settings.warmup().isZero()) {
              figures.add(
                  new Summary.Entry(
                      "warm-up",
                      String.format(
                          Locale.ROOT,
                          "%.2f s simulated before the run, in virtual time, thrown away",
                          settings.warmup().toNanos() / 1e9)));
            }
            lateness.entry().ifPresent(figures::add);
            figures.addAll(crew.figures());
            figures.addAll(loop);
          }
        }
        if (ran < cycles) {
          trace.write(Replay.incomplete(ran, cycles));
        }
      } catch (IOException e) {
        throw new UncheckedIOException(
            "cannot write the trace " + settings.out().resolve(TRACE), e);
      }
      if (ran > 0) { // interrupted before its first cycle, a run has nothing to draw
        Outputs.write(example.name(), Views.of(scene), recording, staging.dir());
      }
      staging.keep();
      if (ran < cycles) {
        out.printf(
            Locale.ROOT,
            "%sarmgals %s: interrupted after %d of %d cycles (%.2f s simulated); the trace up to"
                + " there (marked incomplete)%s %s in %s%n",
            terminal ? System.lineSeparator() : "",
            example.name(),
            ran,
            cycles,
            recording.seconds(),
            ran > 0 ? " and the pictures" : "",
            ran > 0 ? "are" : "is",
            settings.out());
        out.flush();
        throw new RunInterrupted(example.name() + " was interrupted after " + ran + " cycles");
      }
      return recording.summary(missed + crewMissed, figures, settings.out());
    }
  }

  /**
   * The warm-up before a run paced to real time ({@link RunSettings#warmup()}): the same example,
   * in the same world with the same seed, for the warm-up's length rounded up to a cycle, in
   * virtual time with its meta level in this JVM, through the very code a run's cycles go through
   * (trace, samples, the watcher's bookkeeping) into sinks that keep nothing; its crew writes into
   * {@code scratch}, deleted after. What it leaves is code the JIT compiler has compiled, so that
   * the run's first cycles take about what its later ones take instead of several periods each.
   * Answers the real time it took; stops early when {@code interruption} is requested.
   *
   * @throws IllegalArgumentException if the example's robots run in JVMs of their own ({@link
   *     SimExample#usesBroker()}), which a warm-up in this one would not warm
   */
  static Duration warmUp(
      SimExample example,
      RunSettings settings,
      Path scratch,
      TimeSource clock,
      Interruption interruption) {
    if (example.usesBroker()) {
      throw new IllegalArgumentException(
          "'"
              + example.name()
              + "' runs its robots in JVMs of their own, which a warm-up in this one would not"
              + " warm: --warmup-seconds does not apply to it");
    }
    long cycles = warmUpCycles(settings.warmup(), settings.period());
    long start = clock.nanoTime();
    try (Staging staging = Staging.in(scratch)) {
      RunSettings warm = settings.warmUp(cycles, staging.dir());
      Scene scene = example.scene(warm);
      try (Simulation sim = build(example, warm, scene, cycles, Writer.nullWriter(), 1.0)) {
        Recording recording = new Recording(scene.params());
        Crew crew = example.start(sim, warm, new RecordingJournal(sim, recording));
        try {
          Watching watching =
              new Watching(
                  RunWatcher.NONE, sim, scene, crew.reflection().orElse(null), Writer.nullWriter());
          Progress progress =
              new Progress(new PrintStream(OutputStream.nullOutputStream()), false, cycles, clock);
          drive(
              sim,
              cycles,
              warm,
              recording,
              progress,
              interruption,
              watching,
              1.0,
              new Lateness(warm.period().toNanos()));
        } finally {
          crew.close();
        }
      }
    }
    return Duration.ofNanos(clock.nanoTime() - start);
  }

  /**
   * The cycles a warm-up of {@code warmup} runs at {@code period}: rounded up, so that a warm-up of
   * any length runs at least one.
   */
  static long warmUpCycles(Duration warmup, Duration period) {
    long p = period.toNanos();
    long w = warmup.toNanos();
    return w / p + (w % p == 0 ? 0 : 1);
  }

  /**
   * Runs {@code example} with {@code settings} and writes its trace to {@code trace}, nothing else:
   * what a replay compares with the trace of the original run.
   */
  static void traceOnly(SimExample example, RunSettings settings, Writer trace) {
    traceOnly(example, settings, trace, cycles(example, settings));
  }

  /**
   * As {@link #traceOnly(SimExample, RunSettings, Writer)}, stopping after {@code limit} cycles.
   */
  static void traceOnly(SimExample example, RunSettings settings, Writer trace, long limit) {
    traceOnly(example, settings, trace, limit, null);
  }

  /**
   * As {@link #traceOnly(SimExample, RunSettings, Writer, long)}, also writing the reflective
   * loop's record into {@code loopDir} if it is given and the example has a meta level.
   */
  static void traceOnly(
      SimExample example,
      RunSettings settings,
      Writer trace,
      long limit,
      @org.jspecify.annotations.Nullable Path loopDir) {
    checkBroker(example, settings);
    Scene scene = example.scene(settings);
    long cycles = cycles(example, settings);
    BufferedWriter buffered = new BufferedWriter(trace);
    try (Simulation sim = build(example, settings, scene, cycles, buffered, 1.0)) {
      Recording recording = new Recording(scene.params());
      Crew crew = example.start(sim, settings, new RecordingJournal(sim, recording));
      try {
        long ran = Math.min(limit, cycles);
        for (long i = 0; i < ran; i++) {
          sim.runCycle();
        }
        if (loopDir != null && ran > 0) {
          crew.finish(loopDir);
        }
      } finally {
        crew.close();
      }
    }
    try {
      buffered.flush();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write the trace", e);
    }
  }

  /** The number of cycles a run lasts: given, or its simulated time rounded up to a cycle. */
  static long cycles(SimExample example, RunSettings settings) {
    if (settings.cycles().isPresent()) {
      return settings.cycles().getAsLong();
    }
    Duration time = settings.simulated().orElse(example.defaultDuration());
    long period = settings.period().toNanos();
    return Math.max(1, Math.ceilDiv(time.toNanos(), period));
  }

  private static void checkBroker(SimExample example, RunSettings settings) {
    if (settings.broker().isPresent() && !example.usesBroker()) {
      throw new IllegalArgumentException(
          "'"
              + example.name()
              + "' runs in one runtime, without a broker: --broker applies to robots spread"
              + " over several runtimes, such as 'distributed'");
    }
  }

  private static Simulation build(
      SimExample example,
      RunSettings settings,
      Scene scene,
      long cycles,
      Writer trace,
      double speed) {
    SimulationBuilder builder =
        Simulation.builder(scene)
            .seed(settings.seed())
            .controlPeriod(settings.period())
            .legDynamics(settings.legs())
            .trace(trace)
            .traceAttribute(EXAMPLE, example.name())
            .traceAttribute(CYCLES, Long.toString(cycles))
            .traceAttribute(PERIOD_NANOS, Long.toString(settings.period().toNanos()))
            .traceAttribute(LEGS, legs(settings));
    settings.atoms().ifPresent(n -> builder.traceAttribute(ATOMS, Integer.toString(n)));
    if ((settings.realTime() || Reflection.replaying())
        && example.metaLevel(settings).isPresent()) {
      builder.traceAttribute(PACING, FREE);
    }
    if (settings.realTime()) {
      builder.pacer(Pacer.realTime(speed));
    }
    return builder.build();
  }

  /** The settings' leg model as the command line and the trace write it. */
  static String legs(RunSettings settings) {
    return settings.legs().name().toLowerCase(Locale.ROOT);
  }

  /** Runs up to {@code cycles} cycles, telling {@code lateness} of each; answers those it ran. */
  private static long drive(
      Simulation sim,
      long cycles,
      RunSettings settings,
      Recording recording,
      Progress progress,
      Interruption interruption,
      Watching watching,
      double speed,
      Lateness lateness) {
    long i = 0;
    // The schedule starts with the first cycle, as the pacer's does: not at the crew's start (a
    // meta level's JVM starting, say), nor before a first cycle slowed by the JVM's warming up.
    long origin = 0;
    while (i < cycles && !interruption.requested()) {
      sim.runCycle();
      i++;
      recording.sample(sim);
      watching.after(i - 1);
      if (settings.realTime()) {
        long elapsed = progress.elapsedNanos();
        if (i == 1) {
          origin = elapsed - (long) (sim.timeNanos() / speed);
        } else {
          lateness.ended(i - 1, (long) ((elapsed - origin) * speed) - sim.timeNanos());
        }
      }
      progress.update(i, sim.timeNanos());
    }
    return i;
  }

  private static String millis(Duration period) {
    return period.toNanos() % 1_000_000 == 0
        ? Long.toString(period.toMillis())
        : String.format(Locale.ROOT, "%.3f", period.toNanos() / 1e6);
  }

  /**
   * What a run tells its watcher after each cycle, and the robots' programs it writes into {@value
   * #PROGRAMS} when they change. The metas' models are asked for every {@value #MODEL_EVERY}
   * cycles, and a frame carries the last they answered.
   */
  private static final class Watching {
    static final int MODEL_EVERY = 10;

    private final RunWatcher watcher;
    private final Simulation sim;
    private final Scene scene;
    private final @org.jspecify.annotations.Nullable Reflection reflection;
    private final Writer programs;
    private final java.util.Map<String, Object> models =
        new java.util.concurrent.ConcurrentSkipListMap<>();
    private java.util.Map<String, Object> last = java.util.Map.of();

    Watching(
        RunWatcher watcher,
        Simulation sim,
        Scene scene,
        @org.jspecify.annotations.Nullable Reflection reflection,
        Writer programs) {
      this.watcher = watcher;
      this.sim = sim;
      this.scene = scene;
      this.reflection = reflection;
      this.programs = programs;
    }

    void after(long cycle) {
      java.util.Map<String, Object> now =
          reflection == null ? java.util.Map.of() : reflection.programs();
      if (!now.equals(last)) {
        now.forEach(
            (robot, program) -> {
              if (!program.equals(last.get(robot))) {
                java.util.Map<String, Object> line = new java.util.LinkedHashMap<>();
                line.put("cycle", cycle);
                line.put("robot", robot);
                if (program instanceof java.util.Map<?, ?> m) {
                  line.putAll(cast(m));
                }
                write(LoopJson.write(line));
              }
            });
        last = now;
      }
      if (watcher == RunWatcher.NONE) {
        return;
      }
      if (reflection != null && cycle % MODEL_EVERY == 0) {
        reflection.models(models::put);
      }
      List<org.armgals.maam.sim.AtomSensors> atoms = new java.util.ArrayList<>();
      for (int id : sim.atomIds()) {
        atoms.add(sim.sensors(id));
      }
      watcher.frame(
          cycle,
          LiveJson.frame(
              cycle,
              atoms.isEmpty() ? sim.timeNanos() : atoms.get(0).timeNanos(),
              atoms,
              scene.params(),
              now,
              new java.util.LinkedHashMap<>(models)));
    }

    private static java.util.Map<String, Object> cast(java.util.Map<?, ?> m) {
      java.util.Map<String, Object> copy = new java.util.LinkedHashMap<>();
      m.forEach((k, v) -> copy.put(String.valueOf(k), v));
      return copy;
    }

    private void write(String line) {
      try {
        programs.write(line);
        programs.write('\n');
      } catch (IOException e) {
        throw new UncheckedIOException("cannot write " + PROGRAMS, e);
      }
    }
  }
}
