package org.armgals.examples.plot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every picture is a readable PNG with something drawn on it; bad input is refused by name. */
class PlotsTest {
  @TempDir Path dir;

  private static BufferedImage read(Path png) throws IOException {
    BufferedImage image = ImageIO.read(png.toFile());
    assertThat(image).as("%s is a PNG", png).isNotNull();
    return image;
  }

  /** How many distinct colours the picture has: a blank one has one or two. */
  private static long colours(BufferedImage image) {
    return java.util.stream.IntStream.range(0, image.getWidth() * image.getHeight())
        .map(i -> image.getRGB(i % image.getWidth(), i / image.getWidth()))
        .distinct()
        .count();
  }

  @Test
  void trajectoryIsWrittenAsAPng() throws IOException {
    List<Point> path = new ArrayList<>();
    for (int i = 0; i < 100; i++) {
      path.add(new Point(i * 0.01, Math.sin(i * 0.1) * 0.2));
    }
    Path png = dir.resolve("trajectory.png");
    Plots.trajectory(Map.of("molecule", path), SceneView.GROUND, png);
    BufferedImage image = read(png);
    assertThat(image.getWidth()).isEqualTo(800);
    assertThat(colours(image)).isGreaterThan(10);
  }

  @Test
  void energyAndTimelineAreWritten() throws IOException {
    Path energy = dir.resolve("sub/energy.png");
    Plots.series(
        "Energy",
        "energy (J)",
        List.of(new Point(0, 10), new Point(1, 8), new Point(2, 5)),
        energy);
    Path adaptations = dir.resolve("adaptations.png");
    Plots.timeline(
        "Adaptations",
        List.of(new Marker(0.5, "add schema climb"), new Marker(1.5, "energy-saving gait")),
        2.0,
        adaptations);
    Path none = dir.resolve("none.png");
    Plots.timeline("Adaptations", List.of(), 2.0, none);
    assertThat(colours(read(energy))).isGreaterThan(10);
    assertThat(colours(read(adaptations))).isGreaterThan(10);
    assertThat(read(none)).isNotNull();
  }

  @Test
  void moleculePictureShowsBothViews() throws IOException {
    AtomView.Vec c = new AtomView.Vec(0, 0, 0.05);
    AtomView a =
        new AtomView(
            "a0",
            c,
            0.03,
            List.of(
                new AtomView.Leg(new AtomView.Vec(0.08, 0, 0.05), true),
                new AtomView.Leg(new AtomView.Vec(0, 0.08, 0.05), false),
                new AtomView.Leg(new AtomView.Vec(0, 0, 0), false)));
    AtomView b =
        new AtomView(
            "a1",
            new AtomView.Vec(0.16, 0, 0.05),
            0.03,
            List.of(new AtomView.Leg(new AtomView.Vec(0.08, 0, 0.05), true)));
    Path png = dir.resolve("molecule-start.png");
    Extent frame = Extent.of(List.of(a, b));
    MoleculePicture.write("start", List.of(a, b), SceneView.GROUND, frame, png);
    BufferedImage image = read(png);
    MoleculePicture.Layout layout = MoleculePicture.Layout.of(frame);
    assertThat(image.getWidth()).isEqualTo(layout.width()).isBetween(480, 960);
    // Both views, the top one above the side one, have the kernel colour somewhere.
    int kernel = 0x4C72B0;
    boolean top = false;
    boolean side = false;
    for (int y = 0; y < image.getHeight(); y++) {
      for (int x = 0; x < image.getWidth(); x++) {
        if ((image.getRGB(x, y) & 0xFFFFFF) == kernel) {
          top |= layout.top().contains(x, y);
          side |= layout.side().contains(x, y);
        }
      }
    }
    assertThat(top).as("top view drawn").isTrue();
    assertThat(side).as("side view drawn").isTrue();
  }

  @Test
  void badInputIsRefusedWithTheValue() {
    assertThatThrownBy(
            () -> Plots.trajectory(Map.of("m", List.of()), SceneView.GROUND, dir.resolve("t.png")))
        .hasMessageContaining("'m'");
    assertThatThrownBy(() -> Plots.series("E", "J", List.of(new Point(0, 1)), dir.resolve("e.svg")))
        .hasMessageContaining("e.svg");
    assertThatThrownBy(() -> new Point(Double.NaN, 0)).hasMessageContaining("NaN");
    assertThatThrownBy(() -> new Marker(-1, "x")).hasMessageContaining("-1");
    assertThatThrownBy(() -> Plots.timeline("A", List.of(), 0, dir.resolve("a.png")))
        .hasMessageContaining("not 0.0");
    Extent frame = new Extent(0, 1, 0, 1, 0, 1);
    assertThatThrownBy(
            () ->
                MoleculePicture.write(
                    "x", List.of(), SceneView.GROUND, frame, dir.resolve("m.png")))
        .hasMessageContaining("at least one atom");
    assertThatThrownBy(() -> new Extent(0, -1, 0, 1, 0, 1)).hasMessageContaining("x 0.0 to -1.0");
  }
}
