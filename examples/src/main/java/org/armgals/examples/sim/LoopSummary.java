package org.armgals.examples.sim;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;

/**
 * What a run's summary says of its reflective loop, from the loop's record ({@link LoopRecorder}):
 * where the meta level ran and how it kept pace, the notifications sent and what its filter let
 * through, its filter changes, its requests and what became of them, the cycles from decision to
 * application, and a meta level lost.
 *
 * @param entries the summary's lines
 */
record LoopSummary(List<Summary.Entry> entries) {

  /**
   * @param overruns the adaptation points that overran their cycle's time budget (real time, so not
   *     in the record)
   */
  static LoopSummary of(
      List<Map<String, Object>> loop,
      boolean hasMeta,
      RunSettings settings,
      boolean remote,
      long overruns,
      List<Long> latencyNanos) {
    return of(
        loop,
        hasMeta,
        settings,
        remote ? "remote, in a JVM of its own over the broker" : "local, in the robots' JVM",
        overruns,
        latencyNanos);
  }

  /**
   * @param place where the meta level ran, as the summary says it
   * @param overruns the adaptation points that overran their cycle's time budget (real time, so not
   *     in the record)
   */
  static LoopSummary of(
      List<Map<String, Object>> loop,
      boolean hasMeta,
      RunSettings settings,
      String place,
      long overruns,
      List<Long> latencyNanos) {
    List<Summary.Entry> entries = new ArrayList<>();
    if (!hasMeta) {
      entries.add(new Summary.Entry("meta level", "none"));
      return new LoopSummary(entries);
    }
    entries.add(
        new Summary.Entry(
            "meta level",
            place
                + (settings.realTime()
                    ? "; free (the robots never wait for it)"
                    : "; in lock step, one cycle behind")));
    Map<String, Integer> count = new HashMap<>();
    Map<String, Long> requestedAt = new HashMap<>();
    Map<String, Long> answeredAt = new HashMap<>();
    List<Long> latencies = new ArrayList<>();
    int passed = 0;
    int changes = 0;
    String lost = null;
    for (Map<String, Object> r : loop) {
      String event = String.valueOf(r.get("event"));
      count.merge(event, 1, Integer::sum);
      long cycle = ((Number) r.get("cycle")).longValue();
      String key = r.get("robot") + "#" + r.get("version");
      switch (event) {
        case "received" -> passed += Boolean.TRUE.equals(r.get("passed")) ? 1 : 0;
        case "filter" -> {
          if (cycle >= 0) {
            changes++;
          }
        }
        case "requested" -> requestedAt.put(key, cycle);
        // Both sides' records of one cycle: the robots' come first, so an answer may precede.
        case "applied", "refused" -> answeredAt.putIfAbsent(key, cycle);
        case "meta-lost", "free" -> {
          if (lost == null) {
            lost = "at cycle " + cycle + " (" + r.getOrDefault("reason", r.get("runtime")) + ")";
          }
        }
        default -> {}
      }
    }
    requestedAt.forEach(
        (key, at) -> {
          Long answered = answeredAt.get(key);
          if (answered != null) {
            latencies.add(answered - at);
          }
        });
    entries.add(
        new Summary.Entry(
            "notifications",
            count.getOrDefault("notified", 0)
                + " sent, "
                + count.getOrDefault("received", 0)
                + " received, "
                + passed
                + " through its filter"));
    entries.add(new Summary.Entry("filter changes while running", Integer.toString(changes)));
    entries.add(
        new Summary.Entry(
            "requests",
            count.getOrDefault("requested", 0)
                + " ("
                + count.getOrDefault("applied", 0)
                + " applied, "
                + count.getOrDefault("refused", 0)
                + " refused, "
                + count.getOrDefault("suppressed", 0)
                + " held back by its damping)"));
    if (!latencies.isEmpty()) {
      latencies.sort(null);
      List<Long> real = new ArrayList<>(latencyNanos);
      real.sort(null);
      entries.add(
          new Summary.Entry(
              "notified to applied",
              String.format(
                      Locale.ROOT,
                      "%d cycles (median), %d at most (p99 %d)",
                      latencies.get(latencies.size() / 2),
                      latencies.get(latencies.size() - 1),
                      percentile(latencies, 0.99))
                  + (real.isEmpty()
                      ? ""
                      : String.format(
                          Locale.ROOT,
                          "; %.0f µs (median), p99 %.0f µs of real time",
                          percentile(real, 0.5) / 1e3,
                          percentile(real, 0.99) / 1e3))));
    }
    if (overruns > 0) {
      entries.add(
          new Summary.Entry(
              "adaptation overruns", overruns + " applied past the cycle's time budget"));
    }
    if (lost != null) {
      entries.add(
          new Summary.Entry(
              "meta level lost", lost + "; the robots ran on, free, with their last program"));
    }
    return new LoopSummary(entries);
  }

  /** The {@code q} quantile of sorted {@code values}, nearest rank. */
  private static long percentile(List<Long> values, double q) {
    int rank = (int) Math.ceil(q * values.size());
    return values.get(Math.max(0, Math.min(values.size() - 1, rank - 1)));
  }
}
