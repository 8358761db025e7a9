package org.armgals.maam;

import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.SensorKey;

/**
 * A perceptor for the tests: emits its sensor's value plus a bias on {@link #OUT}, nothing when it
 * reads 0.
 */
record Sensing(String name, SensorKey<Integer> sensor, int bias) implements Perceptor {

  static final Port<Num> OUT = Port.of("out", Num.class);

  @Override
  public java.util.List<Port<?>> outputs() {
    return java.util.List.of(OUT);
  }

  @Override
  public void perceive(Body body, Outputs out) {
    int value = body.read(sensor);
    if (value != 0) {
      out.emit(OUT, new Num(value + bias));
    }
  }
}
