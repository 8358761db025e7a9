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
import org.armgals.examples.plot.Extent;
import org.armgals.examples.plot.Marker;
import org.armgals.examples.plot.MoleculePicture;
import org.armgals.examples.plot.Plots;
import org.armgals.examples.plot.Point;
import org.armgals.examples.plot.SceneView;

/**
 * The pictures a run leaves, each as PNG and as SVG beside it: its plots, the molecule at the start
 * and at the end (in one frame: the extent of the molecule at both and of the atoms' paths, so that
 * the end is drawn where the molecule went), and, for a run with a meta level, its reflective loop
 * on a time line ({@value #LOOP}, drawn from the loop's record the run left beside them). The
 * scene's ground and obstacles are in the trajectory and in both molecule pictures.
 */
final class Outputs {
  static final String TRAJECTORY = "trajectory.png";
  static final String ENERGY = "energy.png";
  static final String ADAPTATIONS = "adaptations.png";
  static final String START = "molecule-start.png";
  static final String END = "molecule-end.png";
  static final String LOOP = "reflective-loop.png";

  private Outputs() {}

  /** The SVG written beside the PNG {@code png}. */
  static String svg(String png) {
    return png.substring(0, png.length() - ".png".length()) + ".svg";
  }

  /**
   * Draws the pictures of {@code recording} in {@code scene} into {@code dir}, which holds the
   * run's trace and, if the run had a reflective side, the loop's record.
   */
  static void write(String example, SceneView scene, Recording recording, Path dir) {
    Map<String, List<Point>> paths = new LinkedHashMap<>();
    recording.paths().forEach((id, path) -> paths.put("atom " + id, path));
    Plots.trajectory(paths, scene, dir.resolve(TRAJECTORY));
    Plots.series(example + ": energy left", "energy (J)", recording.energy(), dir.resolve(ENERGY));
    List<Marker> markers =
        recording.adaptations().stream().map(a -> new Marker(a.seconds(), a.what())).toList();
    Plots.timeline(
        example + ": adaptations", markers, recording.seconds(), dir.resolve(ADAPTATIONS));
    Extent frame = frame(recording);
    MoleculePicture.write(
        example + " at the start", recording.first(), scene, frame, dir.resolve(START));
    MoleculePicture.write(
        String.format(Locale.ROOT, "%s at %.2f s", example, recording.lastSeconds()),
        recording.last(),
        scene,
        frame,
        dir.resolve(END));
    Path loop = dir.resolve(Reflection.LOOP);
    if (Files.exists(loop)) {
      LoopTimeline timeline = LoopTimeline.read(loop, period(dir.resolve(SimRun.TRACE)));
      if (timeline.metaLevel()) {
        timeline.write(example + ": the reflective loop", recording.seconds(), dir.resolve(LOOP));
      }
    }
  }

  /**
   * The frame of a run's molecule pictures: the molecule at the start, at the end, and the paths.
   */
  static Extent frame(Recording recording) {
    Extent frame = Extent.of(recording.first()).union(Extent.of(recording.last()));
    for (List<Point> path : recording.paths().values()) {
      for (Point p : path) {
        frame = frame.including(p.x(), p.y(), frame.minZ());
      }
    }
    return frame;
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
