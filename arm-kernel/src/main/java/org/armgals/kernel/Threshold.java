package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

/**
 * A threshold on a numeric observed value with hysteresis: the value is <em>below</em> once it
 * falls under {@code low} and <em>above</em> once it rises over {@code high}, and keeps its side in
 * between. An entity whose {@link NotificationPolicy} watches a threshold emits a {@link
 * ThresholdEvent} (a meta-event, paper §2.3) when the side changes, whatever else it notifies; a
 * value oscillating inside the band emits nothing.
 *
 * @param name the name of the threshold, carried by its events
 * @param property the observed value it watches (a key of {@link
 *     org.armgals.representation.State#observe()})
 * @param low the value under which it is below
 * @param high the value over which it is above, at least {@code low}
 */
public record Threshold(String name, String property, double low, double high) {

  /** Checks the components. */
  public Threshold {
    requireNonNull(name, "name");
    requireNonNull(property, "property");
    if (name.isBlank() || property.isBlank()) {
      throw new IllegalArgumentException(
          "name and property must not be blank, were '" + name + "', '" + property + "'");
    }
    if (!(low <= high)) {
      throw new IllegalArgumentException(
          "low must be <= high (a hysteresis band), were " + low + " and " + high);
    }
  }

  /** A threshold with no band: below under {@code value}, above over it. */
  public static Threshold at(String name, String property, double value) {
    return new Threshold(name, property, value, value);
  }
}
