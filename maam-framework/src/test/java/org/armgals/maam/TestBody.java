package org.armgals.maam;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.SensorKey;

/**
 * The body of this module's own tests: sensors the test sets, the last command of each actuator.
 * The body test double users have, {@code FakeBody}, is in armgals-testkit-maam, a module built
 * after this one, which this module's tests therefore cannot use (docs/decisions/0053).
 */
public final class TestBody implements Body {
  private final String id;
  private final Map<SensorKey<?>, Object> sensors = new ConcurrentHashMap<>();
  private final Set<ActuatorKey<?>> actuators;
  private final Map<ActuatorKey<?>, Object> last = new ConcurrentHashMap<>();

  private TestBody(String id, Map<SensorKey<?>, ?> sensors, Set<ActuatorKey<?>> actuators) {
    this.id = id;
    this.sensors.putAll(sensors);
    this.actuators = Set.copyOf(actuators);
  }

  /** A body named {@code id} with no sensor and no actuator. */
  public static TestBody empty(String id) {
    return new TestBody(id, Map.of(), Set.of());
  }

  /** A body named {@code id} with {@code sensors} at their initial values and {@code actuators}. */
  static TestBody of(String id, Map<SensorKey<?>, ?> sensors, Set<ActuatorKey<?>> actuators) {
    return new TestBody(id, sensors, actuators);
  }

  /** Makes {@code sensor} read {@code value} from now on. */
  <T> void set(SensorKey<T> sensor, T value) {
    if (!sensors.containsKey(sensor)) {
      throw new IllegalArgumentException(id + " has no sensor " + sensor);
    }
    sensors.put(sensor, value);
  }

  /** The last command {@code actuator} received, if any. */
  <T> Optional<T> lastCommand(ActuatorKey<T> actuator) {
    return Optional.ofNullable(actuator.type().cast(last.get(actuator)));
  }

  @Override
  public String id() {
    return id;
  }

  @Override
  public Set<SensorKey<?>> sensors() {
    return Set.copyOf(sensors.keySet());
  }

  @Override
  public Set<ActuatorKey<?>> actuators() {
    return actuators;
  }

  @Override
  public <T> T read(SensorKey<T> sensor) {
    Object value = sensors.get(sensor);
    if (value == null) {
      throw new IllegalArgumentException(id + " has no sensor " + sensor);
    }
    return sensor.type().cast(value);
  }

  @Override
  public <T> void command(ActuatorKey<T> actuator, T value) {
    if (!actuators.contains(actuator)) {
      throw new IllegalArgumentException(id + " has no actuator " + actuator);
    }
    last.put(actuator, actuator.type().cast(value));
  }
}
