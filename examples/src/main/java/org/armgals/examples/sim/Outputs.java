package org.armgals.examples.sim;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.examples.plot.Marker;
import org.armgals.examples.plot.MoleculePicture;
import org.armgals.examples.plot.Plots;
import org.armgals.examples.plot.Point;

/**
 * The pictures a run leaves: its plots, the molecule at the start and at the end, and, for a run
 * with a meta level, its reflective loop on a time line ({@value #LOOP}, drawn from the loop's
 * record the run left beside them).
 */
final class Outputs {
  static final String TRAJECTORY = "trajectory.png";
  static final String ENERGY = "energy.png";
  static final String ADAPTATIONS = "adaptations.png";
  static final String START = "molecule-start.png";
  static final String END = "molecule-end.png";
  static final String LOOP = "reflective-loop.png";

  private Outputs() {}

  /**
   * Draws the pictures of {@code recording} into {@code dir}, which holds the run's trace and, if
   * the run had a reflective side, the loop's record.
   */
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
    Path loop = dir.resolve(Reflection.LOOP);
    if (Files.exists(loop)) {
      LoopTimeline timeline = LoopTimeline.read(loop, period(dir.resolve(SimRun.TRACE)));
      if (timeline.metaLevel()) {
        timeline.write(example + ": the reflective loop", recording.seconds(), dir.resolve(LOOP));
      }
    }
  }

  /** The control period the header of {@code trace} gives. */
  private static Duration period(Path trace) {
    try (BufferedReader in = Files.newBufferedReader(trace, StandardCharsets.UTF_8)) {
      String header = in.readLine();
      if (header == null) {
        throw new IllegalStateException("the trace " + trace + " is empty: it has no header");
      }
      return Replay.Header.parse(header).period();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read the trace's header " + trace, e);
    }
  }
}
