package org.armgals.examples.plot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.w3c.dom.Document;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;

/**
 * The pictures show the world: the scene in every view, one fixed frame with graduated axes,
 * labelled axes, exactly equal scales on the trajectory, and an SVG beside every PNG. Measured on
 * the rendered pictures: pixels of the PNG, text of the SVG parsed as XML.
 */
class PicturesShowTheWorldTest {
  @TempDir Path dir;

  /** A step across the way: x from 0.4 to 0.6 m, 0.1 m high. */
  private static final SceneView STEP =
      new SceneView(
          List.of(
              new SceneView.Block(
                  new AtomView.Vec(0.4, -0.5, 0), new AtomView.Vec(0.6, 0.5, 0.1))));

  private static BufferedImage png(Path png) throws IOException {
    BufferedImage image = ImageIO.read(png.toFile());
    assertThat(image).as("%s is a PNG", png).isNotNull();
    return image;
  }

  /** The SVG beside {@code png}, parsed (its DTD is never fetched). */
  private static Document svg(Path png)
      throws IOException, SAXException, ParserConfigurationException {
    Path svg = Picture.svgBeside(png);
    assertThat(svg).as("the SVG beside %s", png).isNotEmptyFile();
    DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
    factory.setFeature("http://apache.org/xml/features/nonvalidating/load-external-dtd", false);
    Document doc = factory.newDocumentBuilder().parse(svg.toFile());
    assertThat(
            doc.getDocumentElement().getLocalName() == null
                ? doc.getDocumentElement().getTagName()
                : doc.getDocumentElement().getLocalName())
        .isEqualTo("svg");
    return doc;
  }

  /** Every text the SVG writes. */
  private static List<String> texts(Document svg) {
    NodeList nodes = svg.getElementsByTagName("text");
    List<String> texts = new ArrayList<>();
    for (int i = 0; i < nodes.getLength(); i++) {
      texts.add(nodes.item(i).getTextContent().strip());
    }
    return texts;
  }

  private static int count(BufferedImage image, Rectangle2D area, java.awt.Color colour) {
    int n = 0;
    for (int y = (int) area.getMinY(); y < (int) area.getMaxY(); y++) {
      for (int x = (int) area.getMinX(); x < (int) area.getMaxX(); x++) {
        if ((image.getRGB(x, y) & 0xFFFFFF) == (colour.getRGB() & 0xFFFFFF)) {
          n++;
        }
      }
    }
    return n;
  }

  private static Rectangle2D whole(BufferedImage image) {
    return new Rectangle2D.Double(0, 0, image.getWidth(), image.getHeight());
  }

  /** A square path of side {@code side} m from (x0, y0), and maybe one more far point. */
  private static List<Point> square(double x0, double y0, double side) {
    List<Point> path = new ArrayList<>();
    double[][] corners = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    for (int c = 0; c + 1 < corners.length; c++) {
      for (int i = 0; i < 20; i++) {
        double f = i / 20.0;
        path.add(
            new Point(
                x0 + side * (corners[c][0] + f * (corners[c + 1][0] - corners[c][0])),
                y0 + side * (corners[c][1] + f * (corners[c + 1][1] - corners[c][1]))));
      }
    }
    path.add(new Point(x0, y0));
    return path;
  }

  /**
   * Coloured pixels (the path; the grid, the axes and the text are grey) in the row that has most
   * of them, and in the column that has most: the square's side across and up, in pixels. An
   * anti-aliased edge is the path's colour blended with the white under it, still coloured.
   */
  private static int[] sides(BufferedImage image) {
    int[] rows = new int[image.getHeight()];
    int[] columns = new int[image.getWidth()];
    for (int y = 0; y < image.getHeight(); y++) {
      for (int x = 0; x < image.getWidth(); x++) {
        int rgb = image.getRGB(x, y);
        int r = (rgb >> 16) & 0xFF, g = (rgb >> 8) & 0xFF, b = rgb & 0xFF;
        if (Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > 60) {
          rows[y]++;
          columns[x]++;
        }
      }
    }
    return new int[] {
      java.util.Arrays.stream(rows).max().orElseThrow(),
      java.util.Arrays.stream(columns).max().orElseThrow()
    };
  }

  @ParameterizedTest(name = "a square path with a far point at ({0}, {1})")
  @CsvSource({"0.5, 0.5", "3, 0.5", "0.5, 2", "-1.5, -1"})
  void theTrajectoryHasAsManyPixelsPerMetreAcrossAsUp(double farX, double farY) throws IOException {
    // The far point, alone on a path of its own (drawn as nothing), sets the axes' extent.
    Map<String, List<Point>> paths = new LinkedHashMap<>();
    paths.put("square", square(0, 0, 1));
    paths.put("far", List.of(new Point(farX, farY)));
    Path png = dir.resolve("trajectory.png");
    Plots.trajectory(paths, SceneView.GROUND, png);

    int[] sides = sides(png(png));
    assertThat(sides[0]).as("the square's side across, in pixels").isGreaterThan(60);
    assertThat((double) sides[0] / sides[1])
        .as("pixels per metre across over pixels per metre up")
        .isCloseTo(1.0, within(0.02));
  }

  @Test
  void theTrajectoryShowsTheScenesObstacles() throws Exception {
    Path png = dir.resolve("trajectory.png");
    List<Point> path = square(0.3, -0.2, 0.4); // over the step
    Plots.trajectory(Map.of("atom 0", path), STEP, png);
    Plots.trajectory(Map.of("atom 0", path), SceneView.GROUND, dir.resolve("bare.png"));

    BufferedImage image = png(png);
    assertThat(count(image, whole(image), MoleculePicture.SOLID))
        .as("pixels of the step")
        .isGreaterThan(2000);
    BufferedImage bare = png(dir.resolve("bare.png"));
    assertThat(count(bare, whole(bare), MoleculePicture.SOLID)).isZero();
    svg(png);
  }

  private static AtomView atom(String id, double x, double z) {
    return new AtomView(
        id,
        new AtomView.Vec(x, 0, z),
        0.03,
        List.of(
            new AtomView.Leg(new AtomView.Vec(x + 0.08, 0, z), false),
            new AtomView.Leg(new AtomView.Vec(x, 0.08, z), false),
            new AtomView.Leg(new AtomView.Vec(x, 0, z - 0.08), true)));
  }

  @Test
  void theMoleculeIsDrawnOverTheSceneInBothViews() throws IOException {
    Extent frame = Extent.of(List.of(atom("0", 0.2, 0.08), atom("1", 0.7, 0.18)));
    Path png = dir.resolve("molecule-start.png");
    MoleculePicture.write("start", List.of(atom("0", 0.2, 0.08)), STEP, frame, png);

    BufferedImage image = png(png);
    MoleculePicture.Layout layout = MoleculePicture.Layout.of(frame);
    assertThat(image.getHeight()).isEqualTo(layout.height());
    assertThat(image.getWidth()).isEqualTo(layout.width());
    assertThat(count(image, layout.top(), MoleculePicture.SOLID))
        .as("the step from above")
        .isGreaterThan(500);
    assertThat(count(image, layout.side(), MoleculePicture.SOLID))
        .as("the step from the side")
        .isGreaterThan(500);
    assertThat(count(image, layout.side(), MoleculePicture.GROUND))
        .as("the ground from the side")
        .isGreaterThan(500);
    assertThat(count(image, layout.top(), MoleculePicture.KERNEL)).isGreaterThan(50);
    assertThat(count(image, layout.side(), MoleculePicture.KERNEL)).isGreaterThan(50);
  }

  /** The mean x of the kernel's pixels in {@code area}. */
  private static double kernelX(BufferedImage image, Rectangle2D area) {
    double sum = 0;
    int n = 0;
    int kernel = MoleculePicture.KERNEL.getRGB() & 0xFFFFFF;
    for (int y = (int) area.getMinY(); y < (int) area.getMaxY(); y++) {
      for (int x = (int) area.getMinX(); x < (int) area.getMaxX(); x++) {
        if ((image.getRGB(x, y) & 0xFFFFFF) == kernel) {
          sum += x;
          n++;
        }
      }
    }
    assertThat(n).as("kernel pixels").isPositive();
    return sum / n;
  }

  @Test
  void startAndEndAreDrawnInOneFrameWhereTheyAre() throws Exception {
    AtomView start = atom("0", 0.2, 0.08);
    AtomView end = atom("0", 0.5, 0.08);
    Extent frame = Extent.of(List.of(start)).union(Extent.of(List.of(end)));
    Path first = dir.resolve("molecule-start.png");
    Path last = dir.resolve("molecule-end.png");
    MoleculePicture.write("start", List.of(start), SceneView.GROUND, frame, first);
    MoleculePicture.write("end", List.of(end), SceneView.GROUND, frame, last);

    MoleculePicture.Layout layout = MoleculePicture.Layout.of(frame);
    for (Rectangle2D view : List.of(layout.top(), layout.side())) {
      double moved = kernelX(png(last), view) - kernelX(png(first), view);
      assertThat(moved).as("pixels the kernel moved").isCloseTo(0.3 * layout.scale(), within(2.0));
    }
    List<String> texts = texts(svg(first));
    assertThat(texts).contains("x (m)", "y (m)", "z (m)");
    assertThat(texts.stream().filter(t -> t.matches("-?\\d+\\.\\d+")).count())
        .as("graduations, in metres")
        .isGreaterThan(10);
  }

  /** Dark pixels (text) in {@code area}. */
  private static int ink(BufferedImage image, Rectangle2D area) {
    int n = 0;
    for (int y = (int) area.getMinY(); y < (int) area.getMaxY(); y++) {
      for (int x = (int) area.getMinX(); x < (int) area.getMaxX(); x++) {
        int rgb = image.getRGB(x, y);
        if (((rgb >> 16) & 0xFF) < 100 && ((rgb >> 8) & 0xFF) < 100 && (rgb & 0xFF) < 100) {
          n++;
        }
      }
    }
    return n;
  }

  @Test
  void everyPlotHasItsAxesTitledAndItsSvg() throws Exception {
    Path energy = dir.resolve("energy.png");
    Plots.series("energy left", "energy (J)", List.of(new Point(0, 10), new Point(1, 8)), energy);
    Path adaptations = dir.resolve("adaptations.png");
    Plots.timeline("adaptations", List.of(new Marker(0.5, "climb")), 2.0, adaptations);
    Path trajectory = dir.resolve("trajectory.png");
    Plots.trajectory(Map.of("atom 0", square(0, 0, 1)), SceneView.GROUND, trajectory);

    for (Path png : List.of(energy, adaptations, trajectory)) {
      BufferedImage image = png(png);
      // XChart writes an axis's title along the picture's edge, and its text as shapes.
      Rectangle2D leftEdge = new Rectangle2D.Double(0, 0, 22, image.getHeight());
      Rectangle2D bottomEdge =
          new Rectangle2D.Double(0, image.getHeight() - 22, image.getWidth(), 22);
      assertThat(ink(image, leftEdge)).as("the vertical axis's title of %s", png).isGreaterThan(40);
      assertThat(ink(image, bottomEdge)).as("the axis across's title of %s", png).isGreaterThan(40);
      svg(png);
    }
  }

  @Test
  void theLoopPictureHasItsSvg() throws Exception {
    Path png = dir.resolve("reflective-loop.png");
    LoopPicture.write(
        "loop",
        List.of(
            new LoopPicture.Step(0.5, "robot", LoopPicture.Kind.REQUESTED, "addSchema climb"),
            new LoopPicture.Step(0.51, "robot", LoopPicture.Kind.APPLIED, "")),
        List.of(new LoopPicture.Link("robot", 0.5, 0.51, true)),
        1.0,
        png);

    assertThat(png(png).getWidth()).isPositive();
    assertThat(texts(svg(png))).contains("addSchema climb");
  }
}
