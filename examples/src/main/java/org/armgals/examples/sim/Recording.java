package org.armgals.examples.sim;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.examples.cli.Summary;
import org.armgals.examples.plot.AtomView;
import org.armgals.examples.plot.Point;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.Simulation;

/**
 * What a run keeps for its pictures and its summary: every atom's position on the ground plane and
 * the energy left, once per cycle; the molecule at the start and at the end; the adaptations. Used
 * by the thread that runs the simulation only.
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
  private double[] startCentre = {0, 0};
  private double[] endCentre = {0, 0};

  Recording(AtomParams params) {
    this.params = params;
  }

  void sample(Simulation sim) {
    List<AtomView> views = new ArrayList<>();
    double total = 0;
    double x = 0;
    double y = 0;
    for (int id : sim.atomIds()) {
      AtomSensors sensors = sim.atom(id).sensors();
      paths
          .computeIfAbsent(id, k -> new ArrayList<>())
          .add(new Point(sensors.position().x(), sensors.position().y()));
      total += sensors.energy();
      x += sensors.position().x();
      y += sensors.position().y();
      views.add(Views.of(sensors, params));
    }
    int n = Math.max(1, sim.atomIds().size());
    seconds = sim.timeNanos() / 1e9;
    energy.add(new Point(seconds, total));
    if (first.isEmpty()) {
      first = List.copyOf(views);
      startEnergy = total;
      startCentre = new double[] {x / n, y / n};
    }
    last = List.copyOf(views);
    endEnergy = total;
    endCentre = new double[] {x / n, y / n};
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

  double seconds() {
    return seconds;
  }

  /** How far the molecule's centre went on the ground plane (m). */
  double distance() {
    return Math.hypot(endCentre[0] - startCentre[0], endCentre[1] - startCentre[1]);
  }

  /** An atom's diameter, tip to tip with its legs straight (m). */
  double atomDiameter() {
    return 2 * (params.kernelRadius() + params.legLength());
  }

  Summary summary(long missedCycles, List<Summary.Entry> figures, Path dir) {
    List<Summary.Entry> entries = new ArrayList<>();
    entries.add(entry("simulated time", "%.2f s", seconds));
    entries.add(entry("distance", "%.3f m", distance()));
    entries.add(
        entry(
            "speed",
            "%.3f atom diameters/s (%.2f m each)",
            seconds > 0 ? distance() / atomDiameter() / seconds : 0.0,
            atomDiameter()));
    entries.add(entry("energy used", "%.1f J", startEnergy - endEnergy));
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
