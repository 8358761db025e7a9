package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import de.erichseifert.vectorgraphics2d.VectorGraphics2D;
import de.erichseifert.vectorgraphics2d.svg.SVGProcessor;
import de.erichseifert.vectorgraphics2d.util.PageSize;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;
import javax.imageio.ImageIO;

/**
 * Writes the pictures of this package: each drawn once on a {@link Graphics2D}, off screen, and
 * written twice, as a PNG and, beside it under the same name, as SVG (VectorGraphics2D records the
 * drawing's shapes and text), making the directory if needed.
 */
final class Picture {
  private Picture() {}

  /** Pictures are drawn off screen: never ask for a display. Called before AWT is first used. */
  static void headless() {
    System.setProperty("java.awt.headless", "true");
  }

  /**
   * Checks that {@code png} names a {@code .png} file.
   *
   * @throws IllegalArgumentException naming {@code png} if it does not
   */
  static void checkPng(Path png, String what) {
    requireNonNull(png, "png");
    if (!png.getFileName().toString().endsWith(".png")) {
      throw new IllegalArgumentException("a " + what + " is written to a .png file, not " + png);
    }
  }

  /** The SVG file written beside {@code png}: the same name, ending in {@code .svg}. */
  static Path svgBeside(Path png) {
    String name = png.getFileName().toString();
    return png.resolveSibling(name.substring(0, name.length() - ".png".length()) + ".svg");
  }

  /**
   * Draws {@code drawing} on a white {@code width} by {@code height} canvas and writes it to {@code
   * png} and to the {@linkplain #svgBeside SVG beside it}.
   */
  static void write(int width, int height, Consumer<Graphics2D> drawing, Path png, String what) {
    checkPng(png, what);
    BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
    Graphics2D g = image.createGraphics();
    try {
      draw(g, width, height, drawing);
    } finally {
      g.dispose();
    }
    VectorGraphics2D vector = new VectorGraphics2D();
    draw(vector, width, height, drawing);
    Path svg = svgBeside(png);
    try {
      Path parent = png.toAbsolutePath().getParent();
      if (parent != null) {
        Files.createDirectories(parent);
      }
      if (!ImageIO.write(image, "png", png.toFile())) {
        throw new IllegalStateException("this JDK has no PNG writer");
      }
      try (OutputStream out = Files.newOutputStream(svg)) {
        new SVGProcessor()
            .getDocument(vector.getCommands(), new PageSize(0, 0, width, height))
            .writeTo(out);
      }
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write the " + what + " " + png + " or " + svg, e);
    } finally {
      vector.dispose();
    }
  }

  private static void draw(Graphics2D g, int width, int height, Consumer<Graphics2D> drawing) {
    g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
    g.setRenderingHint(
        RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
    g.setColor(Color.WHITE);
    g.fillRect(0, 0, width, height);
    drawing.accept(g);
  }
}
