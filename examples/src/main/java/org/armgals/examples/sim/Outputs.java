package org.armgals.examples.sim;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.examples.plot.Marker;
import org.armgals.examples.plot.MoleculePicture;
import org.armgals.examples.plot.Plots;
import org.armgals.examples.plot.Point;

/** The pictures a run leaves: its plots and the molecule at the start and at the end. */
final class Outputs {
  static final String TRAJECTORY = "trajectory.png";
  static final String ENERGY = "energy.png";
  static final String ADAPTATIONS = "adaptations.png";
  static final String START = "molecule-start.png";
  static final String END = "molecule-end.png";

  private Outputs() {}

  static void write(String example, Recording recording, Path dir) {
    Map<String, List<Point>> paths = new LinkedHashMap<>();
    recording.paths().forEach((id, path) -> paths.put("atom " + id, path));
    Plots.trajectory(paths, dir.resolve(TRAJECTORY));
    Plots.series(example + ": energy left", "energy (J)", recording.energy(), dir.resolve(ENERGY));
    List<Marker> markers =
        recording.adaptations().stream().map(a -> new Marker(a.seconds(), a.what())).toList();
    Plots.timeline(
        example + ": adaptations", markers, recording.seconds(), dir.resolve(ADAPTATIONS));
    MoleculePicture.write(example + " at the start", recording.first(), dir.resolve(START));
    MoleculePicture.write(
        String.format(Locale.ROOT, "%s at %.2f s", example, recording.lastSeconds()),
        recording.last(),
        dir.resolve(END));
  }
}
