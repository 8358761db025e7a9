package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.LegSensors;
import org.armgals.maam.sim.Quat;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Vec3;
import org.armgals.maam.spi.Leg;

/**
 * A run's trace read back for {@code armgals view}: the live view's events ({@link LiveJson}) of
 * each cycle the trace holds, with the records of the reflective loop ({@value Reflection#LOOP})
 * and the robots' programs ({@value SimRun#PROGRAMS}) the run left beside it, if it did. The metas'
 * models are not in a trace: a frame played back has none. Frames are made as they are asked for.
 */
public final class Playback {
  private final String start;
  private final AtomParams params;
  private final List<String> cycles;
  private final Map<Long, List<String>> loop;
  private final List<Map<?, ?>> programChanges;
  private final long of;

  /** One cycle played back: its frame, and the loop's records of that cycle. */
  public record Cycle(long cycle, String frame, List<String> loop) {}

  private Playback(
      String start,
      AtomParams params,
      List<String> cycles,
      Map<Long, List<String>> loop,
      List<Map<?, ?>> programChanges,
      long of) {
    this.start = start;
    this.params = params;
    this.cycles = cycles;
    this.loop = loop;
    this.programChanges = programChanges;
    this.of = of;
  }

  /**
   * Reads {@code trace}, the text of a trace of {@code example} whose header is {@code header}, and
   * what its run left in {@code dir} beside it.
   *
   * @throws UncheckedIOException a file beside it cannot be read
   */
  public static Playback read(SimExample example, Replay.Header header, String trace, Path dir) {
    requireNonNull(example, "example");
    requireNonNull(header, "header");
    requireNonNull(trace, "trace");
    requireNonNull(dir, "dir");
    Scene scene = example.scene(header.settings(dir));
    String start =
        LiveJson.start("view", example.name(), scene, header.cycles(), header.period(), 1.0);
    List<String> cycles = trace.lines().filter(l -> l.startsWith("{\"type\":\"cycle\"")).toList();
    Map<Long, List<String>> loop = new TreeMap<>();
    for (String line : lines(dir.resolve(Reflection.LOOP))) {
      Map<?, ?> record = (Map<?, ?>) TraceJson.parse(line);
      long cycle = Math.max(0, ((Number) record.get("cycle")).longValue());
      loop.computeIfAbsent(cycle, k -> new ArrayList<>()).add(line);
    }
    List<Map<?, ?>> programs = new ArrayList<>();
    for (String line : lines(dir.resolve(SimRun.PROGRAMS))) {
      programs.add((Map<?, ?>) TraceJson.parse(line));
    }
    return new Playback(start, scene.params(), cycles, loop, programs, header.cycles());
  }

  /** The start event. */
  public String start() {
    return start;
  }

  /** How many cycles the trace holds. */
  public int size() {
    return cycles.size();
  }

  /** The end event, once the last cycle is played. */
  public String end() {
    return LiveJson.end(cycles.size(), of);
  }

  /**
   * The {@code index}th cycle the trace holds.
   *
   * @throws IndexOutOfBoundsException not one of them
   * @throws IllegalArgumentException its line is not a cycle of a trace
   */
  public Cycle cycle(int index) {
    Map<?, ?> line = (Map<?, ?>) TraceJson.parse(cycles.get(index));
    long cycle = number(line, "cycle").longValue();
    long nanos = number(line, "t").longValue();
    List<AtomSensors> atoms = new ArrayList<>();
    for (Object atom : (List<?>) line.get("atoms")) {
      atoms.add(atom((Map<?, ?>) atom, nanos));
    }
    Map<String, Object> programs = new LinkedHashMap<>();
    for (Map<?, ?> change : programChanges) {
      if (number(change, "cycle").longValue() <= cycle) {
        Map<String, Object> program = new LinkedHashMap<>();
        program.put("schemas", change.get("schemas"));
        program.put("schedule", change.get("schedule"));
        programs.put(String.valueOf(change.get("robot")), program);
      }
    }
    String frame = LiveJson.frame(cycle, nanos, atoms, params, programs, Map.of());
    return new Cycle(cycle, frame, loop.getOrDefault(cycle, List.of()));
  }

  private static AtomSensors atom(Map<?, ?> a, long nanos) {
    List<?> p = (List<?>) a.get("p");
    List<?> q = (List<?>) a.get("q");
    List<LegSensors> legs = new ArrayList<>();
    List<?> read = (List<?>) a.get("legs");
    for (int i = 0; i < read.size(); i++) {
      List<Number> values = new ArrayList<>();
      for (Object value : (List<?>) read.get(i)) {
        values.add((Number) value);
      }
      legs.add(LegSensors.traced(Leg.values()[i], values));
    }
    return new AtomSensors(
        number(a, "id").intValue(),
        nanos,
        new Vec3(d(p, 0), d(p, 1), d(p, 2)),
        new Quat(d(q, 0), d(q, 1), d(q, 2), d(q, 3)),
        number(a, "tilt").doubleValue(),
        number(a, "energy").doubleValue(),
        Boolean.TRUE.equals(a.get("failed")),
        legs);
  }

  private static double d(List<?> list, int i) {
    return ((Number) list.get(i)).doubleValue();
  }

  private static Number number(Map<?, ?> map, String name) {
    if (!(map.get(name) instanceof Number n)) {
      throw new IllegalArgumentException("a trace line without a number '" + name + "'");
    }
    return n;
  }

  private static List<String> lines(Path file) {
    if (!Files.isRegularFile(file)) {
      return List.of();
    }
    try {
      return Files.readAllLines(file, StandardCharsets.UTF_8).stream()
          .filter(l -> !l.isBlank())
          .toList();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read " + file, e);
    }
  }
}
