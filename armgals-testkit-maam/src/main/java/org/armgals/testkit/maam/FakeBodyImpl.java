package org.armgals.testkit.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.SensorKey;

/** {@link FakeBody}: maps from keys to the current value and to the commands received. */
final class FakeBodyImpl implements FakeBody {

  private final String id;
  private final Map<SensorKey<?>, Object> values;
  private final Map<ActuatorKey<?>, List<Object>> commands;
  private final Set<SensorKey<?>> sensors;
  private final Set<ActuatorKey<?>> actuators;
  private long cycles;

  private FakeBodyImpl(
      String id, Map<SensorKey<?>, Object> values, Set<ActuatorKey<?>> actuatorKeys) {
    this.id = id;
    this.values = new LinkedHashMap<>(values);
    this.commands = new LinkedHashMap<>();
    for (ActuatorKey<?> key : actuatorKeys) {
      commands.put(key, new ArrayList<>());
    }
    this.sensors = Collections.unmodifiableSet(new LinkedHashSet<>(values.keySet()));
    this.actuators = Collections.unmodifiableSet(new LinkedHashSet<>(actuatorKeys));
  }

  @Override
  public String id() {
    return id;
  }

  @Override
  public Set<SensorKey<?>> sensors() {
    return sensors;
  }

  @Override
  public Set<ActuatorKey<?>> actuators() {
    return actuators;
  }

  @Override
  public synchronized <T> T read(SensorKey<T> sensor) {
    requireNonNull(sensor, "sensor");
    Object value = values.get(sensor);
    if (value == null) {
      throw new IllegalArgumentException(
          "sensor " + sensor + ": body '" + id + "' has " + namesOf(sensors));
    }
    return sensor.cast(value);
  }

  @Override
  public synchronized <T> void command(ActuatorKey<T> actuator, T value) {
    log(actuator).add(actuator.cast(value));
  }

  @Override
  public synchronized void endCycle() {
    cycles++;
  }

  @Override
  public synchronized <T> void set(SensorKey<T> sensor, T value) {
    requireNonNull(sensor, "sensor");
    if (!values.containsKey(sensor)) {
      throw new IllegalArgumentException(
          "sensor " + sensor + ": body '" + id + "' has " + namesOf(sensors));
    }
    values.put(sensor, sensor.cast(value));
  }

  @Override
  public synchronized <T> List<T> commands(ActuatorKey<T> actuator) {
    List<T> typed = new ArrayList<>();
    for (Object command : log(actuator)) {
      typed.add(actuator.cast(command));
    }
    return List.copyOf(typed);
  }

  @Override
  public synchronized <T> Optional<T> lastCommand(ActuatorKey<T> actuator) {
    List<Object> log = log(actuator);
    return log.isEmpty() ? Optional.empty() : Optional.of(actuator.cast(log.getLast()));
  }

  @Override
  public synchronized long cycles() {
    return cycles;
  }

  @Override
  public synchronized void clearCommands() {
    commands.values().forEach(List::clear);
  }

  private List<Object> log(ActuatorKey<?> actuator) {
    requireNonNull(actuator, "actuator");
    List<Object> log = commands.get(actuator);
    if (log == null) {
      throw new IllegalArgumentException(
          "actuator " + actuator + ": body '" + id + "' has " + namesOf(actuators));
    }
    return log;
  }

  private static List<String> namesOf(Set<?> keys) {
    List<String> names = new ArrayList<>();
    for (Object key : keys) {
      names.add(
          switch (key) {
            case SensorKey<?> sensor -> sensor.name();
            case ActuatorKey<?> actuator -> actuator.name();
            default -> String.valueOf(key);
          });
    }
    return names;
  }

  /** {@link FakeBody.Builder}: refuses duplicate names. */
  static final class BuilderImpl implements FakeBody.Builder {

    private final String id;
    private final Map<SensorKey<?>, Object> values = new LinkedHashMap<>();
    private final Set<ActuatorKey<?>> actuators = new LinkedHashSet<>();
    private final Set<String> sensorNames = new LinkedHashSet<>();
    private final Set<String> actuatorNames = new LinkedHashSet<>();

    BuilderImpl(String id) {
      this.id = requireNonNull(id, "id");
      if (id.isBlank()) {
        throw new IllegalArgumentException("id '" + id + "': expected not blank");
      }
    }

    @Override
    public <T> Builder sensor(SensorKey<T> sensor, T initial) {
      requireNonNull(sensor, "sensor");
      T value = sensor.cast(initial);
      if (!sensorNames.add(sensor.name())) {
        throw new IllegalArgumentException(
            "sensor '" + sensor.name() + "': expected a name not already in " + sensorNames);
      }
      values.put(sensor, value);
      return this;
    }

    @Override
    public Builder actuator(ActuatorKey<?> actuator) {
      requireNonNull(actuator, "actuator");
      if (!actuatorNames.add(actuator.name())) {
        throw new IllegalArgumentException(
            "actuator '" + actuator.name() + "': expected a name not already in " + actuatorNames);
      }
      actuators.add(actuator);
      return this;
    }

    @Override
    public FakeBody build() {
      return new FakeBodyImpl(id, values, actuators);
    }
  }
}
