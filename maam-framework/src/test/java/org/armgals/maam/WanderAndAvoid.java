package org.armgals.maam;

import java.time.Duration;

/**
 * The tests' small program: a wander perceptor wired to a motor in one schema, and an avoid
 * perceptor, in a schema of its own, that may inhibit the motor. A fresh one per test.
 */
final class WanderAndAvoid {
  final Sensing wander = new Sensing("wander", TestRobot.WANDER, 0);
  final Sensing avoid = new Sensing("avoid", TestRobot.OBSTACLE, 100);
  final Drive motor = new Drive("motor", TestRobot.MOTOR);
  final Schema wandering =
      Schema.builder("wander")
          .add(wander)
          .add(motor)
          .wire(wander, Sensing.OUT, motor, Drive.IN)
          .build();
  final Schema avoiding = Schema.builder("avoid").add(avoid).build();
  final Inhibitor avoidInhibitsMotor =
      new Inhibitor(PortRef.of(avoid, Sensing.OUT), PortRef.of(motor, Drive.IN), Duration.ZERO);
}
