package org.armgals.examples.plot;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/** Writes the pictures of this package: off screen, as PNG, making the directory if needed. */
final class Png {
  private Png() {}

  /** Pictures are drawn off screen: never ask for a display. Called before AWT is first used. */
  static void headless() {
    System.setProperty("java.awt.headless", "true");
  }

  static void write(BufferedImage image, Path png, String what) {
    try {
      Path parent = png.toAbsolutePath().getParent();
      if (parent != null) {
        Files.createDirectories(parent);
      }
      if (!ImageIO.write(image, "png", png.toFile())) {
        throw new IllegalStateException("this JDK has no PNG writer");
      }
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write the " + what + " " + png, e);
    }
  }
}
