package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * A drawing of a molecule: seen from above (x, y) on the left, from the side (x, z) on the right,
 * on one scale. Kernels are discs, legs are lines, bound leg tips are filled.
 */
public final class MoleculePicture {
  private static final int PANEL = 480;
  private static final int MARGIN = 30;
  private static final Color KERNEL = new Color(0x4C72B0);
  private static final Color LEG = new Color(0x333333);
  private static final Color BOUND = new Color(0xDD8452);

  static {
    Png.headless();
  }

  private MoleculePicture() {}

  /**
   * Draws {@code atoms} with {@code title} above and writes the picture to {@code png}.
   *
   * @throws IllegalArgumentException if there is no atom
   */
  public static void write(String title, List<AtomView> atoms, Path png) {
    requireNonNull(title, "title");
    requireNonNull(atoms, "atoms");
    requireNonNull(png, "png");
    if (atoms.isEmpty()) {
      throw new IllegalArgumentException("a molecule picture needs at least one atom");
    }
    BufferedImage image = new BufferedImage(2 * PANEL, PANEL + MARGIN, BufferedImage.TYPE_INT_RGB);
    Graphics2D g = image.createGraphics();
    try {
      g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
      g.setColor(Color.WHITE);
      g.fillRect(0, 0, image.getWidth(), image.getHeight());
      g.setColor(Color.BLACK);
      g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 16));
      g.drawString(title, MARGIN, 22);
      double scale = scale(atoms);
      g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
      Box box = Box.of(atoms);
      double midX = (box.minX + box.maxX) / 2;
      panel(
          g,
          atoms,
          scale,
          0,
          "seen from above (x, y)",
          midX,
          (box.minY + box.maxY) / 2,
          AtomView.Vec::y);
      panel(
          g,
          atoms,
          scale,
          PANEL,
          "seen from the side (x, z)",
          midX,
          (box.minZ + box.maxZ) / 2,
          AtomView.Vec::z);
    } finally {
      g.dispose();
    }
    Png.write(image, png, "picture");
  }

  /** Pixels per metre so that everything fits in a panel, on both views. */
  private static double scale(List<AtomView> atoms) {
    Box box = Box.of(atoms);
    double extent = box.maxX - box.minX;
    extent = Math.max(extent, box.maxY - box.minY);
    extent = Math.max(extent, box.maxZ - box.minZ);
    return (PANEL - 2.0 * MARGIN) / Math.max(extent, 1e-3);
  }

  private static void panel(
      Graphics2D g,
      List<AtomView> atoms,
      double scale,
      int left,
      String caption,
      double midX,
      double midV,
      ToDoubleFunction<AtomView.Vec> vertical) {
    int cx = left + PANEL / 2;
    int cy = MARGIN + PANEL / 2;
    g.setColor(Color.GRAY);
    g.drawRect(left + 4, MARGIN, PANEL - 8, PANEL - 8);
    g.drawString(caption, left + 12, MARGIN + 16);
    for (AtomView atom : atoms) {
      int ax = cx + (int) Math.round((atom.centre().x() - midX) * scale);
      int ay = cy - (int) Math.round((vertical.applyAsDouble(atom.centre()) - midV) * scale);
      for (AtomView.Leg leg : atom.legs()) {
        int tx = cx + (int) Math.round((leg.tip().x() - midX) * scale);
        int ty = cy - (int) Math.round((vertical.applyAsDouble(leg.tip()) - midV) * scale);
        g.setColor(LEG);
        g.setStroke(new BasicStroke(2f));
        g.drawLine(ax, ay, tx, ty);
        int r = 4;
        g.setColor(leg.bound() ? BOUND : LEG);
        if (leg.bound()) {
          g.fillOval(tx - r, ty - r, 2 * r, 2 * r);
        } else {
          g.drawOval(tx - r, ty - r, 2 * r, 2 * r);
        }
      }
      int rr = Math.max(3, (int) Math.round(atom.radius() * scale));
      g.setColor(KERNEL);
      g.fillOval(ax - rr, ay - rr, 2 * rr, 2 * rr);
      g.setColor(Color.BLACK);
      g.drawString(atom.id(), ax + rr + 2, ay - rr);
    }
  }

  /** The bounding box of the atoms' kernels and leg tips. */
  private record Box(double minX, double maxX, double minY, double maxY, double minZ, double maxZ) {
    static Box of(List<AtomView> atoms) {
      double minX = Double.MAX_VALUE, maxX = -Double.MAX_VALUE;
      double minY = Double.MAX_VALUE, maxY = -Double.MAX_VALUE;
      double minZ = Double.MAX_VALUE, maxZ = -Double.MAX_VALUE;
      for (AtomView atom : atoms) {
        double r = atom.radius();
        AtomView.Vec c = atom.centre();
        minX = Math.min(minX, c.x() - r);
        maxX = Math.max(maxX, c.x() + r);
        minY = Math.min(minY, c.y() - r);
        maxY = Math.max(maxY, c.y() + r);
        minZ = Math.min(minZ, c.z() - r);
        maxZ = Math.max(maxZ, c.z() + r);
        for (AtomView.Leg leg : atom.legs()) {
          AtomView.Vec t = leg.tip();
          minX = Math.min(minX, t.x());
          maxX = Math.max(maxX, t.x());
          minY = Math.min(minY, t.y());
          maxY = Math.max(maxY, t.y());
          minZ = Math.min(minZ, t.z());
          maxZ = Math.max(maxZ, t.z());
        }
      }
      return new Box(minX, maxX, minY, maxY, minZ, maxZ);
    }
  }
}
