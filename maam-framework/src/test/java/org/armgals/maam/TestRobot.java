package org.armgals.maam;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.SensorKey;

/**
 * A robot for the tests, on a generic fake body with two integer sensors and one integer actuator,
 * and a time source the test advances one period per cycle.
 */
final class TestRobot extends AbstractRobot {

  static final SensorKey<Integer> WANDER = SensorKey.of("wander", Integer.class);
  static final SensorKey<Integer> OBSTACLE = SensorKey.of("obstacle", Integer.class);
  static final ActuatorKey<Integer> MOTOR = ActuatorKey.of("motor", Integer.class);
  static final ActuatorKey<Integer> OTHER_MOTOR = ActuatorKey.of("other-motor", Integer.class);
  static final long PERIOD = Duration.ofMillis(10).toNanos();

  final TestBody fake;
  final TestTime time;
  final List<String> errors = new ArrayList<>();

  private TestRobot(TestBody body, TestTime time) {
    super("test-robot", body, time);
    this.fake = body;
    this.time = time;
    setErrorHandler((robot, where, error) -> errors.add(where + ": " + error.getMessage()));
  }

  static TestRobot create() {
    TestBody body =
        TestBody.of("test-body", Map.of(WANDER, 0, OBSTACLE, 0), Set.of(MOTOR, OTHER_MOTOR));
    return new TestRobot(body, new TestTime());
  }

  /**
   * Runs one cycle with the sensors reading {@code wander} and {@code obstacle}; returns the
   * motor's command.
   */
  int step(int wander, int obstacle) {
    fake.set(WANDER, wander);
    fake.set(OBSTACLE, obstacle);
    cycle();
    time.now += PERIOD;
    return fake.lastCommand(MOTOR).orElseThrow();
  }

  /** Time the test moves by hand. */
  static final class TestTime implements org.armgals.active.TimeSource {
    long now = 1_000_000_000L;

    @Override
    public long nanoTime() {
      return now;
    }
  }
}
