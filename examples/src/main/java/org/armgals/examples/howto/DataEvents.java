package org.armgals.examples.howto;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.jspecify.annotations.Nullable;

/** Events that carry data, handled by an {@link EventProcessor} with a guard. */
final class DataEvents {
  private DataEvents() {}

  // tag::event[]
  /** A data event: an immutable record that names its sender and its destination. */
  record Reading(@Nullable Address sender, Address destination, String room, double celsius)
      implements Event {}

  // end::event[]

  // tag::processor[]
  /** Takes data events; while it is paused, readings wait in its buffer. */
  static final class Logbook implements EventProcessor {
    private final List<String> lines = new ArrayList<>();
    private boolean paused = true;

    @Override
    public boolean isProcessable(Event event) {
      return !paused; // the guard of data events (method requests have their own)
    }

    @Override
    public void process(Event event) {
      switch (event) {
        case Reading r -> lines.add(r.room() + " " + r.celsius());
        default -> throw new IllegalArgumentException("unexpected event " + event);
      }
    }

    void resume() {
      paused = false;
    }

    List<String> lines() {
      return List.copyOf(lines);
    }
  }

  // end::processor[]

  static List<String> run() {
    try (ActiveRuntime runtime = ActiveRuntime.create()) {
      // tag::send-events[]
      ActiveObject<Logbook> logbook = runtime.spawn(new Logbook());
      // From outside any object the sender is null; inside, ActiveContext.self().address().
      logbook.send(new Reading(null, logbook.address(), "hall", 19.5));
      logbook.send(new Reading(null, logbook.address(), "attic", 23.0));
      logbook.send(Logbook::resume); // a method request: not held back by the data-event guard
      List<String> lines = logbook.call(Logbook::lines).getValue(Duration.ofSeconds(5));
      // end::send-events[]
      return lines;
    }
  }
}
