package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.io.StringWriter;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.armgals.examples.run.RunSettings;
import org.armgals.maam.sim.LegDynamics;
import org.jspecify.annotations.Nullable;

/**
 * Runs again the run that wrote a trace, and says whether it wrote the same trace, bit for bit. The
 * trace's header holds what the run needs ({@link Header}); the example re-runs with {@link
 * SimRun#traceOnly} into memory. See docs/decisions/0031-replay-and-skeleton.md.
 */
public final class Replay {
  /** The trace format this armgals reads and writes. */
  static final String FORMAT = "armgals-maam-sim-trace";

  static final int VERSION = 1;

  private static final Pattern CYCLE = Pattern.compile("\"cycle\":(\\d+)");
  private static final Pattern NAME = Pattern.compile("\"(\\w+)\":");
  private static final Pattern ATOM = Pattern.compile("\\{\"id\":(\\d+)");
  private static final int EXCERPT = 48;

  /** How the last line of an incomplete trace begins. */
  private static final String INCOMPLETE = "{\"type\":\"incomplete\"";

  private Replay() {}

  /**
   * What a trace's header says of the run that wrote it.
   *
   * @param example the example's name
   * @param cycles the cycles it ran
   * @param period its control period
   * @param seed its seed
   * @param atoms the number of atoms, if it was given
   * @param free whether its robots ran free of their meta level (paced to real time): its meta
   *     level's requests are then replayed from the loop's record, not decided again
   * @param legs the simulator's leg model
   */
  public record Header(
      String example,
      long cycles,
      Duration period,
      long seed,
      Optional<Integer> atoms,
      boolean free,
      LegDynamics legs) {

    /** Checks the values. */
    public Header {
      requireNonNull(example, "example");
      requireNonNull(period, "period");
      requireNonNull(atoms, "atoms");
      requireNonNull(legs, "legs");
    }

    /**
     * Reads the header line of a trace.
     *
     * @throws IllegalArgumentException if it is not the header of an armgals run's trace of this
     *     version, saying why in one line
     */
    public static Header parse(String line) {
      requireNonNull(line, "line");
      Map<?, ?> header;
      try {
        header = TraceJson.parse(line) instanceof Map<?, ?> map ? map : Map.of();
      } catch (IllegalArgumentException e) {
        throw new IllegalArgumentException("not an armgals trace: its first line is not JSON");
      }
      if (!"header".equals(header.get("type")) || !FORMAT.equals(header.get("format"))) {
        throw new IllegalArgumentException(
            "not an armgals trace: its first line is not a header of format '" + FORMAT + "'");
      }
      if (!(header.get("version") instanceof BigDecimal version)
          || version.compareTo(BigDecimal.valueOf(VERSION)) != 0) {
        throw new IllegalArgumentException(
            "a trace of version "
                + header.get("version")
                + ": this armgals reads version "
                + VERSION
                + "; replay it with the armgals that wrote it");
      }
      Map<?, ?> attributes = header.get("attributes") instanceof Map<?, ?> map ? map : Map.of();
      if (!(attributes.get(SimRun.EXAMPLE) instanceof String example)) {
        throw new IllegalArgumentException(
            "the trace names no example: it was not written by 'armgals run'");
      }
      long cycles = number(attributes, SimRun.CYCLES);
      long periodNanos = number(attributes, SimRun.PERIOD_NANOS);
      if (!(header.get("seed") instanceof BigDecimal seed)) {
        throw new IllegalArgumentException("the trace's header has no seed");
      }
      Optional<Integer> atoms =
          attributes.containsKey(SimRun.ATOMS)
              ? Optional.of(Math.toIntExact(number(attributes, SimRun.ATOMS)))
              : Optional.empty();
      LegDynamics legs = legs(attributes.get(SimRun.LEGS));
      try {
        return new Header(
            example,
            cycles,
            Duration.ofNanos(periodNanos),
            seed.longValueExact(),
            atoms,
            SimRun.FREE.equals(attributes.get(SimRun.PACING)),
            legs);
      } catch (ArithmeticException e) {
        throw new IllegalArgumentException("the trace's seed " + seed + " is not a whole number");
      }
    }

    /** The trace's leg model; none: written before decision 0065, on jointed legs. */
    private static LegDynamics legs(@Nullable Object value) {
      if (value == null) {
        return LegDynamics.JOINTED;
      }
      for (LegDynamics model : LegDynamics.values()) {
        if (model.name().equalsIgnoreCase(String.valueOf(value))) {
          return model;
        }
      }
      throw new IllegalArgumentException(
          "the trace's attribute '" + SimRun.LEGS + "' is " + value + ", not kinematic or jointed");
    }

    private static long number(Map<?, ?> attributes, String name) {
      Object value = attributes.get(name);
      try {
        return Long.parseLong(String.valueOf(value));
      } catch (NumberFormatException e) {
        throw new IllegalArgumentException(
            "the trace's attribute '" + name + "' is " + value + ", not a whole number");
      }
    }

    /** The settings of a run like the one that wrote the trace, writing nothing to {@code out}. */
    public RunSettings settings(Path out) {
      return new RunSettings(
          OptionalLong.of(cycles),
          Optional.empty(),
          period,
          seed,
          atoms,
          false,
          Optional.empty(),
          out,
          RunSettings.MetaPlace.LOCAL,
          Duration.ZERO,
          legs);
    }
  }

  /** What a replay found. */
  public sealed interface Verdict {
    /** The line a person reads. */
    String line();
  }

  /**
   * The re-run wrote the same trace.
   *
   * @param cycles the cycles of the trace
   * @param sha256 the trace's SHA-256, in hex
   */
  public record Reproduced(long cycles, String sha256) implements Verdict {
    @Override
    public String line() {
      return "reproduced exactly: " + cycles + " cycles, trace sha-256 " + sha256;
    }
  }

  /**
   * The re-run wrote another trace.
   *
   * @param cycle the first cycle that differs, or -1 for the header
   * @param detail where in the line, and both texts there
   */
  public record Differs(long cycle, String detail) implements Verdict {
    @Override
    public String line() {
      return (cycle < 0 ? "differs in the header: " : "differs from cycle " + cycle + ": ")
          + detail;
    }
  }

  /**
   * The re-run wrote the same trace as far as the trace goes, which is not to the end of its run:
   * the run was interrupted (the trace's last line says so), or the trace stops in the middle of a
   * line (the run was killed).
   *
   * @param cycles the cycles the trace has
   * @param of the cycles its run was to last
   * @param why why the trace stops there
   * @param sha256 the SHA-256 of the trace's complete lines, in hex
   */
  public record ReproducedUpTo(long cycles, long of, String why, String sha256) implements Verdict {
    @Override
    public String line() {
      return "reproduced exactly up to where the trace stops ("
          + why
          + "): "
          + cycles
          + " of "
          + of
          + " cycles, trace sha-256 "
          + sha256;
    }
  }

  /**
   * The last line of the trace of a run that was interrupted after {@code cycles} of the {@code of}
   * cycles it was to run.
   */
  static String incomplete(long cycles, long of) {
    return INCOMPLETE
        + ",\"cycles\":"
        + cycles
        + ",\"of\":"
        + of
        + ",\"reason\":\"interrupted\"}\n";
  }

  /**
   * Re-runs {@code example} as {@code header} says and compares what it writes with {@code trace},
   * the whole text of the trace that {@code header} was read from. A trace that stops before the
   * end of its run (its last line marks it incomplete, or it stops in the middle of a line) is
   * compared with the re-run as far as it goes.
   */
  public static Verdict replay(SimExample example, Header header, String trace) {
    return replay(example, header, trace, null);
  }

  /**
   * {@link #replay(SimExample, Header, String)} of the trace of a run that left its reflective
   * loop's record ({@value Reflection#LOOP}) in {@code runDir}: a run in lock step must leave the
   * same record again, compared after the trace; a free run ({@link Header#free()}) is re-run with
   * its meta level's requests applied where the record says they were, so that its trace comes out
   * the same.
   *
   * @param runDir the run's directory, or null: the trace alone is replayed
   */
  public static Verdict replay(
      SimExample example, Header header, String trace, @Nullable Path runDir) {
    requireNonNull(example, "example");
    requireNonNull(header, "header");
    requireNonNull(trace, "trace");
    Path loop = runDir == null ? null : runDir.resolve(Reflection.LOOP);
    if (loop == null || !Files.exists(loop)) {
      if (header.free()) {
        return new Differs(
            -1,
            "a free run is replayed from its loop's record, "
                + Reflection.LOOP
                + ", which is not beside the trace");
      }
      return replayTrace(example, header, trace, null);
    }
    String written = read(loop);
    Path again = tempDir();
    try {
      Verdict verdict =
          header.free()
              ? Reflection.replaying(
                  records(written), () -> replayTrace(example, header, trace, again))
              : replayTrace(example, header, trace, again);
      if (header.free() || !(verdict instanceof Reproduced)) {
        return verdict; // a free run's meta level was not re-run; a cut run's record is partial
      }
      String rerun = read(again.resolve(Reflection.LOOP));
      if (!rerun.equals(written)) {
        Verdict loopVerdict = compare("\n" + written, "\n" + rerun);
        long cycle = loopVerdict instanceof Differs d ? d.cycle() : -1;
        return new Differs(
            cycle,
            "the trace is reproduced, but not the reflective loop's record ("
                + Reflection.LOOP
                + "): "
                + (loopVerdict instanceof Differs d ? d.detail() : "it differs"));
      }
      return verdict;
    } finally {
      deleteRecursively(again);
    }
  }

  private static Verdict replayTrace(
      SimExample example, Header header, String trace, @Nullable Path loopDir) {
    String complete = trace;
    String why = null;
    if (!trace.isEmpty() && !trace.endsWith("\n")) {
      complete = trace.substring(0, trace.lastIndexOf('\n') + 1);
      why = "it stops in the middle of a line: its run was killed";
    } else {
      int last = trace.lastIndexOf('\n', trace.length() - 2) + 1;
      if (trace.startsWith(INCOMPLETE, last)) {
        complete = trace.substring(0, last);
        why = "the run was interrupted";
      }
    }
    long cycles = Math.max(0, complete.lines().count() - 1);
    StringWriter again = new StringWriter();
    SimRun.traceOnly(
        example,
        header.settings(Path.of(".")),
        again,
        why == null ? header.cycles() : cycles,
        loopDir);
    Verdict verdict = compare(complete, again.toString());
    if (why != null && verdict instanceof Reproduced reproduced) {
      return new ReproducedUpTo(reproduced.cycles(), header.cycles(), why, reproduced.sha256());
    }
    return verdict;
  }

  private static List<Map<String, Object>> records(String loop) {
    List<Map<String, Object>> records = new java.util.ArrayList<>();
    long order = 0;
    for (String line : loop.lines().toList()) {
      if (!line.isBlank() && TraceJson.parse(line) instanceof Map<?, ?> m) {
        LoopRecorder.Line l = LoopRecorder.read(m, order++);
        Map<String, Object> record = new java.util.LinkedHashMap<>();
        record.put("cycle", l.cycle());
        record.putAll(l.fields());
        records.add(record);
      }
    }
    return records;
  }

  private static String read(Path file) {
    try {
      return Files.readString(file, StandardCharsets.UTF_8);
    } catch (java.io.IOException e) {
      throw new java.io.UncheckedIOException("cannot read " + file, e);
    }
  }

  private static Path tempDir() {
    try {
      return Files.createTempDirectory("armgals-replay");
    } catch (java.io.IOException e) {
      throw new java.io.UncheckedIOException("cannot make a directory for the replay's loop", e);
    }
  }

  private static void deleteRecursively(Path dir) {
    try (java.util.stream.Stream<Path> files = Files.walk(dir)) {
      for (Path f : files.sorted(java.util.Comparator.reverseOrder()).toList()) {
        Files.deleteIfExists(f);
      }
    } catch (java.io.IOException e) {
      throw new java.io.UncheckedIOException("cannot delete " + dir, e);
    }
  }

  /** Compares the trace as written with the trace of the re-run. */
  static Verdict compare(String written, String rerun) {
    List<String> a = written.lines().toList();
    if (written.equals(rerun)) {
      return new Reproduced(Math.max(0, a.size() - 1), sha256(written));
    }
    List<String> b = rerun.lines().toList();
    for (int i = 0; i < Math.max(a.size(), b.size()); i++) {
      if (i >= a.size()) {
        return new Differs(cycleOf(b.get(i), i), "the trace ends before it; the re-run goes on");
      }
      if (i >= b.size()) {
        return new Differs(cycleOf(a.get(i), i), "the re-run ends before it");
      }
      if (!a.get(i).equals(b.get(i))) {
        return new Differs(i == 0 ? -1 : cycleOf(a.get(i), i), where(a.get(i), b.get(i)));
      }
    }
    return new Differs(cycleOf(a.get(a.size() - 1), a.size() - 1), "line endings differ");
  }

  private static long cycleOf(String line, int index) {
    Matcher m = CYCLE.matcher(line);
    return index == 0 ? -1 : m.find() ? Long.parseLong(m.group(1)) : index - 1;
  }

  /** The first field that differs, with both texts from there. */
  private static String where(String written, String rerun) {
    int at = 0;
    while (at < written.length() && at < rerun.length() && written.charAt(at) == rerun.charAt(at)) {
      at++;
    }
    String before = written.substring(0, at);
    int from = 0;
    String field = null;
    Matcher name = NAME.matcher(before);
    while (name.find()) {
      from = name.start();
      field = name.group(1);
    }
    String atom = "";
    int atoms = before.indexOf("\"atoms\":[");
    int events = before.indexOf("\"events\":");
    Matcher id = ATOM.matcher(before);
    while (id.find()) {
      if (atoms >= 0 && id.start() > atoms && (events < 0 || id.start() < events)) {
        atom = "atom " + id.group(1) + ", ";
      }
    }
    String place = field == null ? "" : atom + "field '" + field + "': ";
    return place + "trace has " + excerpt(written, from) + ", the re-run " + excerpt(rerun, from);
  }

  private static String excerpt(String line, int from) {
    String rest = line.substring(Math.min(from, line.length()));
    return rest.length() <= EXCERPT ? rest : rest.substring(0, EXCERPT) + "…";
  }

  private static String sha256(String text) {
    try {
      MessageDigest digest = MessageDigest.getInstance("SHA-256");
      return HexFormat.of().formatHex(digest.digest(text.getBytes(StandardCharsets.UTF_8)));
    } catch (NoSuchAlgorithmException e) {
      throw new IllegalStateException("every Java platform has SHA-256", e);
    }
  }
}
