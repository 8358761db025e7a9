package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * A drawing of a molecule in its world: seen from above (x across, y up) and, below, from the side
 * (x across, z up, looking along +y), both on one scale and over the same x, as an engineering
 * drawing lays out a plan above an elevation. Kernels are discs, legs are lines, bound leg tips are
 * filled; the ground (z = 0) and the scene's obstacles are drawn under them; both views have their
 * axes graduated in metres.
 *
 * <p>The views show a given {@link Extent} of the world, not the molecule's own: the pictures of a
 * run share one frame, so that the molecule at the end is drawn where it went, away from where it
 * started.
 */
public final class MoleculePicture {
  /** The widest picture: a long molecule, or one that went far along x, has this width. */
  static final int WIDTH = 960;

  static final int LEFT = 80;
  static final int RIGHT = 24;
  static final int TOP = 40;
  static final int CAPTION = 22;
  static final int BELOW = 48;
  static final int BOTTOM = 8;

  /** The most pixels the two views take, one above the other. */
  static final int MAX_VIEWS_HEIGHT = 760;

  static final Color KERNEL = new Color(0x4C72B0);
  static final Color LEG = new Color(0x333333);
  static final Color BOUND = new Color(0xDD8452);
  static final Color SOLID = new Color(0xB4B1A8);
  static final Color SOLID_EDGE = new Color(0x7A7A7A);
  static final Color GROUND = new Color(0xC9B48F);
  static final Color GRID = new Color(0xE4E4E4);
  private static final Font TITLE = new Font(Font.SANS_SERIF, Font.BOLD, 16);
  // 13, not 12: VectorGraphics2D leaves the size of a 12-point font out of the SVG, and a browser
  // then draws it at its own default size.
  private static final Font TEXT = new Font(Font.SANS_SERIF, Font.PLAIN, 13);
  private static final Font TICKS = new Font(Font.SANS_SERIF, Font.PLAIN, 11);

  static {
    Picture.headless();
  }

  private MoleculePicture() {}

  /**
   * Draws {@code atoms} in {@code scene} over {@code frame} (grown by a margin, and down to below
   * the ground), with {@code title} above, and writes the picture to {@code png} and as SVG beside
   * it.
   *
   * @throws IllegalArgumentException if there is no atom, or if {@code png} does not end in {@code
   *     .png}
   */
  public static void write(
      String title, List<AtomView> atoms, SceneView scene, Extent frame, Path png) {
    requireNonNull(title, "title");
    requireNonNull(atoms, "atoms");
    requireNonNull(scene, "scene");
    requireNonNull(frame, "frame");
    Picture.checkPng(png, "picture");
    if (atoms.isEmpty()) {
      throw new IllegalArgumentException("a molecule picture needs at least one atom");
    }
    Layout layout = Layout.of(frame);
    Picture.write(
        layout.width(),
        layout.height(),
        g -> {
          g.setColor(Color.BLACK);
          g.setFont(TITLE);
          g.drawString(title, LEFT, 26);
          view(g, layout, layout.top(), 1, "seen from above", atoms, scene);
          view(g, layout, layout.side(), 2, "seen from the side (looking along +y)", atoms, scene);
        },
        png,
        "picture");
  }

  /**
   * Where things go on the picture: the world's extent shown, the scale, and each view's rectangle
   * in pixels.
   */
  record Layout(
      Extent shown, double scale, Rectangle2D top, Rectangle2D side, int width, int height) {

    static Layout of(Extent frame) {
      double size =
          Math.max(
              frame.maxX() - frame.minX(),
              Math.max(frame.maxY() - frame.minY(), frame.maxZ() - frame.minZ()));
      double margin = Math.max(0.02, 0.06 * size);
      Extent grown = frame.grown(margin);
      // The ground shows: the side view goes down to a margin below z = 0.
      Extent shown = grown.including(grown.minX(), grown.minY(), -margin);
      double dx = shown.maxX() - shown.minX();
      double dy = shown.maxY() - shown.minY();
      double dz = shown.maxZ() - shown.minZ();
      double scale = Math.min((WIDTH - LEFT - RIGHT) / dx, MAX_VIEWS_HEIGHT / (dy + dz));
      double w = dx * scale;
      double topY = TOP + CAPTION;
      Rectangle2D top = new Rectangle2D.Double(LEFT, topY, w, dy * scale);
      double sideY = top.getMaxY() + BELOW + CAPTION;
      Rectangle2D side = new Rectangle2D.Double(LEFT, sideY, w, dz * scale);
      // As wide as the views once their height has set the scale, never below half the most.
      int width = (int) Math.max(WIDTH / 2, Math.ceil(LEFT + w + RIGHT));
      return new Layout(
          shown, scale, top, side, width, (int) Math.ceil(side.getMaxY() + BELOW + BOTTOM));
    }

    /** World to pixels in the view of {@code area} whose vertical axis is {@code up} (1 or 2). */
    AffineTransform transform(Rectangle2D area, int up) {
      AffineTransform t = new AffineTransform();
      t.translate(area.getMinX(), area.getMaxY());
      t.scale(scale, -scale);
      t.translate(-shown.minX(), -(up == 1 ? shown.minY() : shown.minZ()));
      return t;
    }
  }

  private static void view(
      Graphics2D g,
      Layout layout,
      Rectangle2D area,
      int up,
      String caption,
      List<AtomView> atoms,
      SceneView scene) {
    AffineTransform world = layout.transform(area, up);
    Extent shown = layout.shown();
    double lowV = up == 1 ? shown.minY() : shown.minZ();
    double highV = up == 1 ? shown.maxY() : shown.maxZ();
    g.setFont(TEXT);
    g.setColor(Color.BLACK);
    g.drawString(caption, (float) area.getMinX(), (float) area.getMinY() - 7);

    Shape clip = g.getClip();
    g.clip(area);
    double stepX = step(shown.maxX() - shown.minX(), area.getWidth());
    double stepV = step(highV - lowV, area.getHeight());
    g.setStroke(new BasicStroke(1f));
    g.setColor(GRID);
    for (double x : ticks(shown.minX(), shown.maxX(), stepX)) {
      g.draw(world.createTransformedShape(new Line2D.Double(x, lowV, x, highV)));
    }
    for (double v : ticks(lowV, highV, stepV)) {
      g.draw(world.createTransformedShape(new Line2D.Double(shown.minX(), v, shown.maxX(), v)));
    }
    if (up == 2) { // the ground, below z = 0
      g.setColor(GROUND);
      g.fill(
          world.createTransformedShape(
              new Rectangle2D.Double(
                  shown.minX(), shown.minZ(), shown.maxX() - shown.minX(), 0 - shown.minZ())));
    }
    for (SceneView.Solid solid : scene.solids()) {
      for (Shape s : solid.projected(0, up)) {
        Shape onPicture = world.createTransformedShape(s);
        g.setColor(SOLID);
        g.fill(onPicture);
        g.setColor(SOLID_EDGE);
        g.draw(onPicture);
      }
    }
    if (up == 2) {
      g.setColor(GROUND.darker());
      g.setStroke(new BasicStroke(1.5f));
      g.draw(world.createTransformedShape(new Line2D.Double(shown.minX(), 0, shown.maxX(), 0)));
    }
    for (AtomView atom : atoms) {
      atom(g, world, atom, up, layout.scale());
    }
    g.setClip(clip);

    g.setColor(Color.GRAY);
    g.setStroke(new BasicStroke(1f));
    g.draw(area);
    axes(g, world, area, up, shown, lowV, highV, stepX, stepV);
  }

  private static void atom(
      Graphics2D g, AffineTransform world, AtomView atom, int up, double scale) {
    double[] c = onPicture(world, atom.centre(), up);
    for (AtomView.Leg leg : atom.legs()) {
      double[] t = onPicture(world, leg.tip(), up);
      g.setColor(LEG);
      g.setStroke(new BasicStroke(2f));
      g.draw(new Line2D.Double(c[0], c[1], t[0], t[1]));
      double r = 4;
      Shape tip = new Ellipse2D.Double(t[0] - r, t[1] - r, 2 * r, 2 * r);
      if (leg.bound()) {
        g.setColor(BOUND);
        g.fill(tip);
      } else {
        g.setStroke(new BasicStroke(1.5f));
        g.draw(tip);
      }
    }
    double rr = Math.max(3, atom.radius() * scale);
    g.setColor(KERNEL);
    g.fill(new Ellipse2D.Double(c[0] - rr, c[1] - rr, 2 * rr, 2 * rr));
    g.setColor(Color.BLACK);
    g.setFont(TEXT);
    g.drawString(atom.id(), (float) (c[0] + rr + 2), (float) (c[1] - rr));
  }

  private static double[] onPicture(AffineTransform world, AtomView.Vec v, int up) {
    double[] p = {v.x(), up == 1 ? v.y() : v.z()};
    world.transform(p, 0, p, 0, 1);
    return p;
  }

  private static void axes(
      Graphics2D g,
      AffineTransform world,
      Rectangle2D area,
      int up,
      Extent shown,
      double lowV,
      double highV,
      double stepX,
      double stepV) {
    g.setFont(TICKS);
    FontMetrics m = g.getFontMetrics();
    g.setColor(Color.BLACK);
    for (double x : ticks(shown.minX(), shown.maxX(), stepX)) {
      double px = onPicture(world, new AtomView.Vec(x, 0, 0), 1)[0];
      g.draw(new Line2D.Double(px, area.getMaxY(), px, area.getMaxY() + 4));
      String label = label(x, stepX);
      g.drawString(
          label,
          (float) (px - m.stringWidth(label) / 2.0),
          (float) area.getMaxY() + 6 + m.getAscent());
    }
    for (double v : ticks(lowV, highV, stepV)) {
      double py = onPicture(world, new AtomView.Vec(0, v, v), up)[1];
      g.draw(new Line2D.Double(area.getMinX() - 4, py, area.getMinX(), py));
      String label = label(v, stepV);
      g.drawString(
          label,
          (float) (area.getMinX() - 7 - m.stringWidth(label)),
          (float) (py + m.getAscent() / 2.0 - 1));
    }
    g.setFont(TEXT);
    FontMetrics t = g.getFontMetrics();
    String across = "x (m)";
    g.drawString(
        across,
        (float) (area.getCenterX() - t.stringWidth(across) / 2.0),
        (float) (area.getMaxY() + 8 + m.getHeight() + t.getAscent()));
    String vertical = up == 1 ? "y (m)" : "z (m)";
    AffineTransform saved = g.getTransform();
    g.translate(area.getMinX() - 52, area.getCenterY() + t.stringWidth(vertical) / 2.0);
    g.rotate(-Math.PI / 2);
    g.drawString(vertical, 0f, 0f);
    g.setTransform(saved);
  }

  /** A step of 1, 2 or 5 times a power of ten giving a tick every 60 pixels or more. */
  static double step(double range, double pixels) {
    double raw = range / Math.max(1, pixels / 60);
    double magnitude = Math.pow(10, Math.floor(Math.log10(raw)));
    for (double m : new double[] {1, 2, 5}) {
      if (m * magnitude >= raw * (1 - 1e-9)) {
        return m * magnitude;
      }
    }
    return 10 * magnitude;
  }

  /** The multiples of {@code step} from {@code low} to {@code high}. */
  static List<Double> ticks(double low, double high, double step) {
    long first = (long) Math.ceil(low / step - 1e-9);
    long last = (long) Math.floor(high / step + 1e-9);
    return java.util.stream.LongStream.rangeClosed(first, last).mapToObj(i -> i * step).toList();
  }

  /** {@code v} with as many decimals as {@code step} needs. */
  static String label(double v, double step) {
    int decimals = Math.max(0, (int) -Math.floor(Math.log10(step) + 1e-9));
    String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
    return s.matches("-0(\\.0*)?") ? s.substring(1) : s;
  }
}
