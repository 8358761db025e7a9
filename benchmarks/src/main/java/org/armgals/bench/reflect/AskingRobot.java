package org.armgals.bench.reflect;

import java.util.List;
import java.util.Map;
import org.armgals.active.TimeSource;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Emission;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.Signal;
import org.armgals.maam.Tunable;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;

/**
 * The robot of {@link Asking}: one schema of one module, a {@link Dial} whose setting its meta
 * changes ({@code setParameter}); it shows its meta the dial's setting ({@value #SETTING}) every
 * cycle. It does nothing else, so that what a run measures is the reflective loop.
 */
final class AskingRobot extends AbstractRobot {
  static final String NAME = "asking";
  static final String DIAL = "dial";
  static final String SETTING = "setting";

  private static final Port<Turned> TURNED = Port.of("turned", Turned.class);

  AskingRobot(Body body, TimeSource time) {
    super(NAME, body, time);
    addSchema(Schema.builder("dial").add(new Dial()).build());
  }

  /** Its kind, {@code AskingRobot}: it observes the dial's {@value #SETTING}. */
  static StructuralMeta<PState> kind(Kernel kernel) {
    return RobotKind.builder("AskingRobot", AskingRobot.class)
        .observing(Map.of(SETTING, 0L))
        .define(kernel);
  }

  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    long setting = 0;
    for (Emission e : emissions()) {
      if (e.signal() instanceof Turned t) {
        setting = t.setting();
      }
    }
    m.put(SETTING, setting);
    return m;
  }

  /** The dial's setting, emitted every cycle. */
  record Turned(long setting) implements Signal {}

  /** A perceptor that emits its setting, which the meta sets. */
  static final class Dial implements Perceptor, Tunable {
    private long setting;

    @Override
    public String name() {
      return DIAL;
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(TURNED);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      out.emit(TURNED, new Turned(setting));
    }

    @Override
    public void tune(String parameter, Object value) {
      if (!SETTING.equals(parameter) || !(value instanceof Number n)) {
        throw new IllegalArgumentException(
            "the dial has a number parameter '" + SETTING + "', not " + parameter + " = " + value);
      }
      setting = n.longValue();
    }
  }
}
