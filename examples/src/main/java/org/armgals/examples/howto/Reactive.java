package org.armgals.examples.howto;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Clock;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.armgals.active.ReactiveCycle;
import org.jspecify.annotations.Nullable;

/** A reactive (synchronous) object on a manual clock. */
final class Reactive {
  private Reactive() {}

  record Temperature(@Nullable Address sender, Address destination, double celsius)
      implements Event {}

  // tag::thermostat[]
  /** Takes the readings of an instant, then decides once per instant (its reactive cycle). */
  static final class Thermostat implements EventProcessor, ReactiveCycle {
    private final List<String> log;
    private double latest = Double.NaN;
    private boolean heating;

    Thermostat(List<String> log) {
      this.log = log;
    }

    @Override
    public void process(Event event) { // first: every event waiting at the release
      if (event instanceof Temperature t) {
        latest = t.celsius();
      }
    }

    @Override
    public void onCycle(long instant) { // then: once per instant
      boolean cold = latest < 19.0;
      if (cold != heating) {
        heating = cold;
        log.add("instant " + instant + ": heater " + (heating ? "on" : "off"));
      }
    }
  }

  // end::thermostat[]

  static List<String> run() {
    List<String> log = Collections.synchronizedList(new ArrayList<>());
    try (ActiveRuntime runtime = ActiveRuntime.create()) {
      // tag::clock[]
      try (ManualClock clock = Clock.manual(Duration.ofMillis(10))) { // 10 ms of virtual time
        ObjectConfig reactive = ObjectConfig.synchronous(clock);
        ActiveObject<Thermostat> thermostat = runtime.spawn(new Thermostat(log), reactive);

        thermostat.send(new Temperature(null, thermostat.address(), 17.0));
        clock.step(); // instant 1 takes the 17.0: "instant 1: heater on"
        thermostat.send(new Temperature(null, thermostat.address(), 22.5));
        clock.step(); // instant 2 takes the 22.5: "instant 2: heater off"
        clock.step(); // instant 3: nothing new, nothing logged
      }
      // end::clock[]
    }
    return List.copyOf(log);
  }
}
