package org.armgals.maam.sim;

import org.armgals.maam.spi.Leg;

/** How scene and trace files name legs: {@code +x}, {@code -x}, … */
final class Legs {

  private static final String[] LABELS = {"+x", "-x", "+y", "-y", "+z", "-z"};

  private Legs() {}

  static String label(Leg leg) {
    return LABELS[leg.ordinal()];
  }

  static Leg ofLabel(String label) {
    for (Leg leg : Leg.values()) {
      if (LABELS[leg.ordinal()].equals(label)) {
        return leg;
      }
    }
    throw new IllegalArgumentException(
        "leg label '" + label + "' is not one of +x, -x, +y, -y, +z, -z");
  }
}
