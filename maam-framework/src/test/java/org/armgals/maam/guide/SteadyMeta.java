package org.armgals.maam.guide;

import java.time.Duration;
import java.util.Locale;
import java.util.Map;
import org.armgals.kernel.Adaptation;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Notification;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;

// tag::meta[]
/**
 * Steadies a balancing atom that leans: its filter lets through only the states in which the atom
 * leans more than 0.2 rad, and on each it asks for a {@code balance} module of a higher gain, up to
 * 5. Its damping keeps 100 ms (of the robot's time) between two changes of one robot, so that a
 * change is judged on cycles run with it. On its meta-entity's own object, never on the robot's
 * thread; in the robot's JVM or in another one.
 */
final class SteadyMeta extends BMetaRobot {
  /** Its filter: a JMS selector over the notifications' properties (the observed values too). */
  static final String LEANING = "kind = 'state' AND lean > 0.2";

  private double gain = 2.0; // the robot's balance module starts with this gain

  SteadyMeta() {
    super("bmbalancer", new Damping(Duration.ofMillis(100), 3, Duration.ofSeconds(10)));
  }

  @Override
  public void onNotification(MetaContext context, Notification n) {
    if (gain >= 5
        || !(observation(n).orElse(Map.of()).get(BalancingAtom.LEAN) instanceof Double lean)) {
      return; // as strong as it goes, or not a state (a lost runtime's failure passes any filter)
    }
    Adaptation stronger =
        RobotKind.because(
            String.format(Locale.ROOT, "leaning %.2f rad", lean),
            RobotKind.changeModule("balance", Map.of(BalancingKind.GAIN, gain + 1)));
    if (context.adapt(n.entity(), stronger).isPresent()) { // empty: held back by the damping
      gain += 1;
    }
  }
}
// end::meta[]
