package org.armgals.maam.guide;

import java.time.Duration;
import java.util.Map;
import org.armgals.active.TimeSource;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Emission;
import org.armgals.maam.PortRef;
import org.armgals.maam.Schema;
import org.armgals.maam.Suppressor;
import org.armgals.maam.guide.Modules.Balance;
import org.armgals.maam.guide.Modules.BatterySensor;
import org.armgals.maam.guide.Modules.LegDrive;
import org.armgals.maam.guide.Modules.Rest;
import org.armgals.maam.guide.Modules.TiltSensor;
import org.armgals.maam.guide.Signals.Tilted;
import org.armgals.maam.spi.Body;

/**
 * Step 4: the robot class, registering the schemas of step 1 and their subsumption, and saying what
 * it shows its meta level.
 */
// tag::robot[]
final class BalancingAtom extends AbstractRobot {
  /** The observed lean, radians: 0 while level. */
  static final String LEAN = "lean";

  BalancingAtom(Body body, TimeSource time) {
    super("balancer", body, time);
    TiltSensor tilt = new TiltSensor("tilt", 0.05);
    Balance balance = new Balance("balance", 2.0);
    LegDrive legs = new LegDrive("legs");
    addSchema(
        Schema.builder("balance")
            .add(tilt)
            .add(balance)
            .add(legs)
            .wire(tilt, Modules.TILTED, balance, Modules.TILTED)
            .wire(balance, Modules.STANCE, legs, Modules.STANCE)
            .build());
    BatterySensor battery = new BatterySensor("battery", 10.0);
    Rest rest = new Rest("rest");
    addSchema(
        Schema.builder("survive")
            .add(battery)
            .add(rest)
            .wire(battery, Modules.LOW, rest, Modules.LOW)
            .build());
    // Resting wins over balancing, and for 50 ms after the battery last looked low.
    addConnector(
        new Suppressor(
            PortRef.of(rest, Modules.STANCE),
            PortRef.of(balance, Modules.STANCE),
            Duration.ofMillis(50)));
  }

  /** What it shows its meta level each cycle: the robot's own values, and how far it leans. */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> seen = super.observe(); // cycle, program, schemas, errors
    double lean = 0;
    for (Emission e : emissions()) { // the signals of this cycle, after suppression
      if (e.signal() instanceof Tilted t) {
        lean = Math.max(Math.abs(t.roll()), Math.abs(t.pitch()));
      }
    }
    seen.put(LEAN, lean);
    return seen;
  }
}
// end::robot[]
