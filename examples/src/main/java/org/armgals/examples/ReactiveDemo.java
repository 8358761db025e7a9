package org.armgals.examples;

import static java.util.Objects.requireNonNull;

import java.io.PrintStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Collectors;
import org.armgals.active.ActiveContext;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Clock;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.FutureValue;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.armgals.active.ReactiveCycle;
import org.jspecify.annotations.Nullable;

/**
 * Part 3 of the demo: two reactive (synchronous) objects on a manual clock. At each instant the
 * sensor emits a reading; the controller sees it at the next instant. The controller also asks the
 * sensor for a value: its future is a synchronous one, which never waits; the reply is an event
 * like any other and shows up two instants later, while the controller keeps reacting.
 */
final class ReactiveDemo {
  private ReactiveDemo() {}

  /** A data event: the value a sensor read at instant {@code emittedAt}. */
  record Reading(Address sender, Address destination, long emittedAt, int value) implements Event {}

  /** One line of the trace: at which instant, which object ({@code rank} orders them), what. */
  record Line(long instant, int rank, String text) {}

  /** Collects what the objects report; any thread. */
  static final class Trace {
    private final List<Line> lines = new ArrayList<>();

    synchronized void add(long instant, int rank, String text) {
      lines.add(new Line(instant, rank, text));
    }

    /** What happened at {@code instant}, the sensor's lines first. */
    synchronized String at(long instant) {
      return lines.stream()
          .filter(l -> l.instant() == instant)
          .sorted(Comparator.comparingInt(Line::rank))
          .map(Line::text)
          .collect(Collectors.joining("; "));
    }
  }

  static final class Sensor implements ReactiveCycle {
    private final ActiveRef<Controller> controller;
    private final Trace trace;

    Sensor(ActiveRef<Controller> controller, Trace trace) {
      this.controller = requireNonNull(controller, "controller");
      this.trace = requireNonNull(trace, "trace");
    }

    int offset() {
      return 7;
    }

    @Override
    public void onCycle(long instant) {
      int value = 10 * (int) instant;
      Address self = ActiveContext.self().address();
      controller.send(new Reading(self, controller.address(), instant, value));
      trace.add(instant, 0, "sensor emits " + value);
    }
  }

  static final class Controller implements EventProcessor, ReactiveCycle {
    private final Trace trace;
    private final List<Reading> readings = new ArrayList<>();
    private @Nullable ActiveRef<Sensor> sensor;
    private @Nullable FutureValue<Integer> offset;
    private long askedAt;

    Controller(Trace trace) {
      this.trace = requireNonNull(trace, "trace");
    }

    void watch(ActiveRef<Sensor> sensor) {
      this.sensor = sensor;
    }

    @Override
    public void process(Event event) {
      if (event instanceof Reading r) {
        readings.add(r);
      }
    }

    // tag::sync-future[]
    @Override
    public void onCycle(long instant) {
      for (Reading r : readings) {
        trace.add(
            instant, 1, "controller sees " + r.value() + " (emitted at " + r.emittedAt() + ")");
      }
      readings.clear();
      FutureValue<Integer> f = offset;
      if (f == null && sensor != null) {
        offset = sensor.call(Sensor::offset); // a SynchronousFutureValue: it never waits
        askedAt = instant;
        trace.add(instant, 1, "controller asks the sensor for its offset");
      } else if (f != null && askedAt > 0) {
        if (f.isDone()) {
          trace.add(instant, 1, "offset " + f.getValue() + " arrived (asked at " + askedAt + ")");
          askedAt = 0;
        } else {
          trace.add(instant, 1, "offset not there yet, the controller goes on");
        }
      }
    }
    // end::sync-future[]
  }

  /** What part 3 printed, one entry per instant. */
  record Result(List<String> instants) {}

  static Result run(ActiveRuntime runtime, PrintStream out, int instants) {
    out.println("3. Two reactive objects on a manual clock: emitted at instant k, seen at k + 1");
    Trace trace = new Trace();
    List<String> seen = new ArrayList<>();
    try (ManualClock clock = Clock.manual(Duration.ofMillis(10))) {
      ObjectConfig reactive = ObjectConfig.synchronous(clock);
      ActiveObject<Controller> controller = runtime.spawn(new Controller(trace), reactive);
      ActiveObject<Sensor> sensor = runtime.spawn(new Sensor(controller, trace), reactive);
      controller.send(c -> c.watch(sensor)); // taken at the first instant, like every event
      for (int i = 0; i < instants; i++) {
        long k = clock.step(); // returns once both objects have finished instant k
        String line = "instant " + k + ": " + trace.at(k);
        seen.add(line);
        out.println("   " + line);
      }
      // What the last instant emitted was meant for an instant that will not come: the part ends
      // by stopping its objects, which discards those events on purpose.
      sensor.stop();
      controller.stop();
    }
    return new Result(seen);
  }
}
