package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.examples.plot.LoopPicture;
import org.armgals.examples.plot.LoopPicture.Kind;
import org.armgals.examples.plot.LoopPicture.Link;
import org.armgals.examples.plot.LoopPicture.Step;
import org.jspecify.annotations.Nullable;

/**
 * A run's reflective loop as its picture shows it, read from the loop's record ({@value
 * Reflection#LOOP}, as {@link LoopRecorder} writes it): each record a step at its cycle times the
 * period (the first filter, set before the run at cycle -1, at 0 s), each request linked to the
 * cycle it was applied or refused at, labelled with the cycles it took. Notifications are labelled
 * with their kind where it is not the robot's usual one (the energy robot's threshold among its
 * states). Records of other events are not drawn.
 *
 * @param steps the steps, in the record's order
 * @param links the requests answered
 * @param metaLevel whether the run had a meta level: the record holds a step of a meta, or the loss
 *     of one (a run without a meta level records nothing)
 */
record LoopTimeline(List<Step> steps, List<Link> links, boolean metaLevel) {

  LoopTimeline {
    steps = List.copyOf(steps);
    links = List.copyOf(links);
  }

  /**
   * Reads the loop's record {@code file} of a run of control period {@code period}.
   *
   * @throws IllegalArgumentException if a line is not a record of the loop, naming the line
   */
  static LoopTimeline read(Path file, Duration period) {
    requireNonNull(file, "file");
    List<Map<?, ?>> records = new ArrayList<>();
    try {
      List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
      for (int i = 0; i < lines.size(); i++) {
        if (lines.get(i).isBlank()) {
          continue;
        }
        if (!(TraceJson.parse(lines.get(i)) instanceof Map<?, ?> record)
            || !(record.get("cycle") instanceof Number)
            || !(record.get("event") instanceof String)
            || !(record.get("robot") instanceof String)) {
          throw new IllegalArgumentException(
              file + " line " + (i + 1) + " is not a record of the loop (cycle, event, robot)");
        }
        records.add(record);
      }
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read the loop's record " + file, e);
    }
    return of(records, period);
  }

  /** The time line of {@code records}, in the order of the loop's record. */
  static LoopTimeline of(List<Map<?, ?>> records, Duration period) {
    requireNonNull(records, "records");
    long nanos = requireNonNull(period, "period").toNanos();
    if (nanos <= 0) {
      throw new IllegalArgumentException("period must be positive, was " + period);
    }
    Map<String, Map<String, Integer>> kinds = new HashMap<>();
    Map<String, Long> requested = new HashMap<>();
    for (Map<?, ?> r : records) {
      if ("notified".equals(r.get("event"))) {
        kinds
            .computeIfAbsent(text(r, "robot"), k -> new HashMap<>())
            .merge(text(r, "kind"), 1, Integer::sum);
      } else if ("requested".equals(r.get("event"))) {
        requested.put(request(r), cycle(r));
      }
    }
    Map<String, String> usual = new HashMap<>();
    kinds.forEach(
        (robot, counts) ->
            usual.put(
                robot,
                counts.entrySet().stream()
                    .max(Map.Entry.comparingByValue())
                    .orElseThrow()
                    .getKey()));
    List<Step> steps = new ArrayList<>();
    List<Link> links = new ArrayList<>();
    boolean metaLevel = false;
    for (Map<?, ?> r : records) {
      String robot = text(r, "robot");
      long cycle = cycle(r);
      double seconds = Math.max(cycle, 0) * (nanos / 1e9);
      metaLevel |= r.containsKey("meta") || "meta-lost".equals(r.get("event"));
      String kindLabel = text(r, "kind").equals(usual.get(robot)) ? "" : text(r, "kind");
      @Nullable Step step =
          switch (text(r, "event")) {
            case "notified" -> new Step(seconds, robot, Kind.SENT, kindLabel);
            case "received" ->
                new Step(
                    seconds,
                    robot,
                    Boolean.TRUE.equals(r.get("passed")) ? Kind.PASSED : Kind.FILTERED_OUT,
                    kindLabel);
            case "filter" ->
                new Step(
                    seconds,
                    robot,
                    Kind.FILTER,
                    text(r, "selector").isEmpty() ? "no selector: all pass" : text(r, "selector"));
            case "requested" -> new Step(seconds, robot, Kind.REQUESTED, text(r, "request"));
            case "suppressed" -> new Step(seconds, robot, Kind.HELD_BACK, text(r, "request"));
            case "applied", "refused" -> {
              boolean applied = "applied".equals(r.get("event"));
              Long decided = requested.get(request(r));
              String label = "";
              if (decided != null) {
                double from = Math.max(decided, 0) * (nanos / 1e9);
                links.add(new Link(robot, from, seconds, applied));
                label = latency(cycle - decided, nanos);
              }
              if (!applied) {
                label = label.isEmpty() ? text(r, "refusal") : label + ": " + text(r, "refusal");
              }
              yield new Step(seconds, robot, applied ? Kind.APPLIED : Kind.REFUSED, label);
            }
            case "note" -> new Step(seconds, robot, Kind.NOTE, text(r, "text"));
            case "free" -> new Step(seconds, robot, Kind.FREE, text(r, "reason"));
            case "meta-lost" ->
                new Step(
                    seconds, robot, Kind.META_LOST, text(r, "runtime") + ": " + text(r, "reason"));
            default -> null;
          };
      if (step != null) {
        steps.add(step);
      }
    }
    return new LoopTimeline(steps, links, metaLevel);
  }

  /** Draws the time line over {@code [0, endSeconds]} into {@code png}. */
  void write(String title, double endSeconds, Path png) {
    LoopPicture.write(title, steps, links, endSeconds, png);
  }

  private static String latency(long cycles, long periodNanos) {
    double millis = cycles * (periodNanos / 1e6);
    return String.format(
        Locale.ROOT,
        millis == Math.rint(millis) ? "+%d cycle%s (%.0f ms)" : "+%d cycle%s (%.2f ms)",
        cycles,
        cycles == 1 ? "" : "s",
        millis);
  }

  private static String request(Map<?, ?> r) {
    return text(r, "robot") + "#" + text(r, "version");
  }

  private static long cycle(Map<?, ?> r) {
    return ((Number) r.get("cycle")).longValue();
  }

  private static String text(Map<?, ?> r, String field) {
    Object value = r.get(field);
    return value == null ? "" : value.toString();
  }
}
