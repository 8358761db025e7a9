package org.armgals.examples.cli;

import java.io.PrintStream;
import java.math.BigDecimal;
import java.net.URI;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.concurrent.Callable;
import org.armgals.examples.live.LiveServer;
import org.armgals.examples.run.Example;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.SimExample;
import org.armgals.maam.sim.LegDynamics;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code armgals run <example>}: runs one example and prints its summary. */
@Command(name = "run", description = "Runs an example robot and prints a summary of its run.")
final class RunCommand implements Callable<Integer> {
  @Mixin HelpOption help = new HelpOption();

  private final Catalog catalog;
  private final PrintStream out;

  /** The longest control period: an hour. */
  static final long MAX_PERIOD_MS = 3_600_000;

  /** The longest run: what {@link Long#MAX_VALUE} nanoseconds hold, in whole seconds. */
  static final long MAX_SECONDS = Long.MAX_VALUE / 1_000_000_000L;

  @Parameters(index = "0", paramLabel = "<example>", description = "the example, as listed")
  String name = "";

  @Option(names = "--cycles", paramLabel = "<n>", description = "control cycles to run")
  Long cycles;

  @Option(
      names = "--seconds",
      paramLabel = "<s>",
      description = "simulated seconds to run (instead of --cycles)")
  Double seconds;

  @Option(
      names = "--period-ms",
      paramLabel = "<ms>",
      defaultValue = "10",
      description = "control period in milliseconds (default ${DEFAULT-VALUE})")
  long periodMs;

  @Option(
      names = "--seed",
      paramLabel = "<n>",
      defaultValue = "1",
      description = "seed of every random choice (default ${DEFAULT-VALUE})")
  long seed;

  @Option(names = "--atoms", paramLabel = "<n>", description = "number of atoms, where it applies")
  Integer atoms;

  @Option(names = "--realtime", description = "pace the run to real time")
  boolean realTime;

  @Option(
      names = "--live",
      description =
          "show the run in a browser while it goes: serves a page on 127.0.0.1 and prints its"
              + " address; the run is paced to real time (times --speed)")
  boolean live;

  @Option(
      names = "--live-port",
      paramLabel = "<port>",
      description = "the port of the live view's page (default: a free one)")
  Integer livePort;

  @Option(
      names = "--speed",
      paramLabel = "<factor>",
      description = "with --live: simulated seconds per real second (default 1)")
  Double speed;

  @Option(
      names = "--warmup-seconds",
      paramLabel = "<s>",
      description =
          "paced to real time: simulated seconds to run first, in virtual time on a scratch copy of"
              + " the world, and throw away, so that the first paced cycles run compiled code"
              + " (default 5 when paced, 0 for robots in JVMs of their own)")
  Double warmupSeconds;

  @Option(names = "--broker", paramLabel = "<url>", description = "an external Artemis broker")
  URI broker;

  @Option(
      names = "--meta",
      paramLabel = "<place>",
      defaultValue = "local",
      converter = MetaPlaceConverter.class,
      description =
          "where the meta level runs: local (in the robots' JVM) or remote (in a JVM of its own,"
              + " over the broker); default ${DEFAULT-VALUE}")
  RunSettings.MetaPlace meta = RunSettings.MetaPlace.LOCAL;

  @Option(
      names = "--legs",
      paramLabel = "<model>",
      defaultValue = "kinematic",
      converter = LegsConverter.class,
      description =
          "the simulator's leg model: kinematic (one body per atom, the robots are tuned for it) or"
              + " jointed (seven bodies per atom, slower; a robot may not walk on it as tuned);"
              + " default ${DEFAULT-VALUE}")
  LegDynamics legs = RunSettings.DEFAULT_LEGS;

  @Option(
      names = "--out",
      paramLabel = "<dir>",
      description = "where the run leaves its trace and pictures (default runs/<example>)")
  Path outDir;

  RunCommand(Catalog catalog, PrintStream out) {
    this.catalog = catalog;
    this.out = out;
  }

  @Override
  public Integer call() {
    Example example =
        catalog
            .find(name)
            .orElseThrow(
                () ->
                    new UsageException(
                        "no example named '" + name + "'; 'armgals list' shows them"));
    check();
    RunSettings settings =
        new RunSettings(
            cycles == null ? OptionalLong.empty() : OptionalLong.of(cycles),
            Optional.ofNullable(seconds).map(RunCommand::simulated),
            Duration.ofMillis(periodMs),
            seed,
            Optional.ofNullable(atoms),
            realTime || live,
            Optional.ofNullable(broker),
            outDir == null ? Path.of("runs", example.name()) : outDir,
            meta,
            warmup(example),
            legs);
    Summary summary = live ? live(example, settings) : example.run(settings, out);
    out.println();
    out.println("summary of " + example.name() + ":");
    int width = summary.entries().stream().mapToInt(e -> e.name().length()).max().orElse(0);
    for (Summary.Entry entry : summary.entries()) {
      out.printf("  %-" + width + "s  %s%n", entry.name(), entry.value());
    }
    return 0;
  }

  /** The run with its live view: the page is served while it runs, and stops when it ends. */
  private Summary live(Example example, RunSettings settings) {
    if (!(example instanceof SimExample simulated)) {
      throw new UsageException(
          "'" + example.name() + "' does not run on the simulator: it has nothing to show live");
    }
    double factor = speed == null ? 1.0 : speed;
    if (!(factor > 0) || Double.isInfinite(factor)) {
      throw new IllegalArgumentException("--speed must be a finite number above 0, was " + factor);
    }
    try (LiveServer server = LiveServer.start(livePort == null ? 0 : livePort)) {
      out.println("armgals: the live view is at " + server.address());
      out.flush();
      return simulated.run(settings, out, server, factor);
    }
  }

  /** Checks each option's range, naming the option as given and its value. */
  private void check() {
    if (cycles != null && cycles < 1) {
      throw new IllegalArgumentException("--cycles must be at least 1, was " + cycles);
    }
    if (periodMs <= 0) {
      throw new IllegalArgumentException("--period-ms must be positive, was " + periodMs);
    }
    if (periodMs > MAX_PERIOD_MS) {
      throw new IllegalArgumentException(
          "--period-ms must be at most " + MAX_PERIOD_MS + " (an hour), was " + periodMs);
    }
    if (!live && (livePort != null || speed != null)) {
      throw new UsageException(
          (livePort != null ? "--live-port" : "--speed") + " applies to a live run: add --live");
    }
    if (livePort != null && (livePort < 0 || livePort > 65_535)) {
      throw new IllegalArgumentException(
          "--live-port must be a port from 1 to 65535, or 0 for a free one; was " + livePort);
    }
    if (atoms != null && atoms < 1) {
      throw new IllegalArgumentException("--atoms must be at least 1, was " + atoms);
    }
  }

  /**
   * {@code --warmup-seconds} as given, or the default: {@link RunSettings#DEFAULT_WARMUP} for a run
   * paced to real time of robots in this JVM, none otherwise.
   */
  private Duration warmup(Example example) {
    boolean paced = realTime || live;
    boolean here = example instanceof SimExample simulated && !simulated.usesBroker();
    if (warmupSeconds == null) {
      return paced && here ? RunSettings.DEFAULT_WARMUP : Duration.ZERO;
    }
    if (warmupSeconds < 0) {
      throw new IllegalArgumentException(
          "--warmup-seconds must be 0 or more, was "
              + BigDecimal.valueOf(warmupSeconds).stripTrailingZeros().toPlainString());
    }
    if (warmupSeconds == 0) {
      return Duration.ZERO;
    }
    if (!paced) {
      throw new UsageException(
          "--warmup-seconds applies to a run paced to real time: add --realtime or --live");
    }
    if (!here) {
      throw new UsageException(
          "--warmup-seconds does not apply to '"
              + example.name()
              + "': its robots run in JVMs of their own, which a warm-up in this one would not"
              + " warm");
    }
    return seconds("--warmup-seconds", warmupSeconds);
  }

  /**
   * {@code --seconds} as a duration: positive, at least a nanosecond, and at most what a count of
   * nanoseconds holds (292 years), so that no run silently lasts one cycle.
   */
  static Duration simulated(double seconds) {
    return seconds("--seconds", seconds);
  }

  /** {@code option}'s value in seconds as a duration, checked as {@link #simulated} says. */
  static Duration seconds(String option, double seconds) {
    if (!Double.isFinite(seconds)) {
      throw new IllegalArgumentException(option + " must be positive and finite, was " + seconds);
    }
    String given = BigDecimal.valueOf(seconds).stripTrailingZeros().toPlainString();
    if (!(seconds > 0)) {
      throw new IllegalArgumentException(option + " must be positive and finite, was " + given);
    }
    if (seconds > MAX_SECONDS) {
      throw new IllegalArgumentException(
          option
              + " must be at most "
              + MAX_SECONDS
              + " (292 years of simulated time, the most a run can count in nanoseconds), was "
              + given);
    }
    long nanos = Math.round(seconds * 1e9);
    if (nanos < 1) {
      throw new IllegalArgumentException(
          option + " must be at least a nanosecond (0.000000001), was " + given);
    }
    return Duration.ofNanos(nanos);
  }

  /** {@code --legs kinematic|jointed}, any case; anything else names the value and the choices. */
  static final class LegsConverter implements CommandLine.ITypeConverter<LegDynamics> {
    @Override
    public LegDynamics convert(String value) {
      for (LegDynamics model : LegDynamics.values()) {
        if (model.name().equalsIgnoreCase(value)) {
          return model;
        }
      }
      throw new CommandLine.TypeConversionException(
          "'" + value + "' is not a leg model; expected kinematic or jointed");
    }
  }

  /** {@code --meta local|remote}, any case; anything else names the value and the choices. */
  static final class MetaPlaceConverter
      implements CommandLine.ITypeConverter<RunSettings.MetaPlace> {
    @Override
    public RunSettings.MetaPlace convert(String value) {
      for (RunSettings.MetaPlace place : RunSettings.MetaPlace.values()) {
        if (place.name().equalsIgnoreCase(value)) {
          return place;
        }
      }
      throw new CommandLine.TypeConversionException(
          "'" + value + "' is not a place for the meta level; expected local or remote");
    }
  }
}
