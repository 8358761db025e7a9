package org.armgals.examples.sim;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.examples.plot.AtomView;
import org.armgals.examples.plot.Point;
import org.armgals.examples.run.Summary;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.Simulation;

/**
 * What a run keeps for its pictures and its summary: every atom's position on the ground plane and
 * the energy left, once per reading; the molecule at the start and at the end; the adaptations.
 * Used by the thread that runs the simulation only.
 *
 * <p>The simulator's sensors are read at the start of a cycle, so after cycle {@code n} they tell
 * the state at the start of cycle {@code n}: a sample is timed by its readings, not by the
 * simulation's clock, and a sample of readings already kept (the scene's initial pose, read again
 * by the first cycle) is skipped. The last sample is thus one period before the end of the run.
 */
final class Recording {

  /** One adaptation a crew told, at {@code seconds} of simulated time. */
  record Adaptation(double seconds, int atom, String what, String why) {}

  private final AtomParams params;
  private final Map<Integer, List<Point>> paths = new LinkedHashMap<>();
  private final List<Point> energy = new ArrayList<>();
  private final List<Adaptation> adaptations = new ArrayList<>();
  private List<AtomView> first = List.of();
  private List<AtomView> last = List.of();
  private double startEnergy;
  private double endEnergy;
  private double seconds;
  private double lastSeconds;
  private long lastReadingNanos = -1;
  private double[] startCentre = {0, 0};
  private double[] endCentre = {0, 0};
  private final List<Point> centres = new ArrayList<>();

  Recording(AtomParams params) {
    this.params = params;
  }

  /** Keeps the readings {@code sim}'s atoms have now, unless they are those of the last sample. */
  void sample(Simulation sim) {
    List<Integer> ids = sim.atomIds();
    long readingNanos = ids.isEmpty() ? sim.timeNanos() : sim.sensors(ids.get(0)).timeNanos();
    if (readingNanos == lastReadingNanos) {
      return;
    }
    lastReadingNanos = readingNanos;
    List<AtomView> views = new ArrayList<>();
    double total = 0;
    double x = 0;
    double y = 0;
    for (int id : sim.atomIds()) {
      AtomSensors sensors = sim.sensors(id);
      paths
          .computeIfAbsent(id, k -> new ArrayList<>())
          .add(new Point(sensors.position().x(), sensors.position().y()));
      total += sensors.energy();
      x += sensors.position().x();
      y += sensors.position().y();
      views.add(Views.of(sensors, params));
    }
    int n = Math.max(1, sim.atomIds().size());
    double at = readingNanos / 1e9;
    energy.add(new Point(at, total));
    if (first.isEmpty()) {
      first = List.copyOf(views);
      startEnergy = total;
      startCentre = new double[] {x / n, y / n};
      endCentre = startCentre;
    }
    last = List.copyOf(views);
    lastSeconds = at;
    endEnergy = total;
    double[] centre = {x / n, y / n};
    centres.add(new Point(centre[0], centre[1]));
    endCentre = centre;
  }

  /**
   * The length of {@code path} at a resolution of {@code resolution} metres: the sum of the
   * straight steps from its start to the next point at least {@code resolution} away, from there to
   * the next, and so on, and on to its end. Wobbles smaller than the resolution (a kernel rocking
   * over its tips at each step of a gait) are not counted as distance; a turn is, to within its
   * chords.
   */
  static double length(List<Point> path, double resolution) {
    if (path.isEmpty()) {
      return 0;
    }
    double length = 0;
    Point from = path.get(0);
    for (Point p : path) {
      double step = Math.hypot(p.x() - from.x(), p.y() - from.y());
      if (step >= resolution) {
        length += step;
        from = p;
      }
    }
    Point end = path.get(path.size() - 1);
    return length + Math.hypot(end.x() - from.x(), end.y() - from.y());
  }

  /** Tells that the run ended at {@code nanos} of simulated time. */
  void end(long nanos) {
    seconds = nanos / 1e9;
  }

  void adaptation(Adaptation adaptation) {
    adaptations.add(adaptation);
  }

  Map<Integer, List<Point>> paths() {
    return paths;
  }

  List<Point> energy() {
    return energy;
  }

  List<Adaptation> adaptations() {
    return adaptations;
  }

  List<AtomView> first() {
    return first;
  }

  List<AtomView> last() {
    return last;
  }

  /** How long the run lasted (s of simulated time). */
  double seconds() {
    return seconds;
  }

  /** When the last sample was read (s of simulated time): the time of {@link #last()}. */
  double lastSeconds() {
    return lastSeconds;
  }

  /**
   * How far the molecule's centre went on the ground plane (m), from the first to the last sample,
   * in a straight line.
   */
  double displacement() {
    return Math.hypot(endCentre[0] - startCentre[0], endCentre[1] - startCentre[1]);
  }

  /**
   * The length of the molecule's centre's path on the ground plane (m), at a resolution of a
   * quarter of an atom's diameter ({@link #length(List, double)}), from the first to the last
   * sample.
   */
  double pathLength() {
    return length(centres, atomDiameter() / 4);
  }

  /** An atom's diameter, tip to tip with its legs straight (m). */
  double atomDiameter() {
    return 2 * (params.kernelRadius() + params.legLength());
  }

  Summary summary(long missedCycles, List<Summary.Entry> figures, Path dir) {
    List<Summary.Entry> entries = new ArrayList<>();
    entries.add(entry("simulated time", "%.2f s", seconds));
    entries.add(entry("displacement", "%.3f m", displacement()));
    entries.add(entry("path length", "%.3f m", pathLength()));
    entries.add(
        entry(
            "speed",
            "%.3f atom diameters/s (%.2f m each)",
            lastSeconds > 0 ? displacement() / atomDiameter() / lastSeconds : 0.0,
            atomDiameter()));
    entries.add(entry("energy used", "%.2f J", startEnergy - endEnergy));
    entries.add(entry("adaptations", "%d", adaptations.size()));
    for (Adaptation a : adaptations) {
      entries.add(
          entry(
              String.format(Locale.ROOT, "  at %.2f s", a.seconds()),
              "atom %d: %s, because %s",
              a.atom(),
              a.what(),
              a.why()));
    }
    entries.add(entry("missed cycles", "%d", missedCycles));
    entries.addAll(figures);
    entries.add(new Summary.Entry("outputs", dir.toString()));
    return new Summary(entries);
  }

  private static Summary.Entry entry(String name, String format, Object... args) {
    return new Summary.Entry(name, String.format(Locale.ROOT, format, args));
  }
}
