package org.armgals.testkit;

import org.armgals.active.ActiveRef;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.jspecify.annotations.Nullable;

/** The messages and the echo object of the testkit's tests. */
final class Messages {
  private Messages() {}

  /** Asks an {@link Echo} for a {@link Pong}. */
  record Ping(Address destination, int n) implements Event {
    @Override
    public @Nullable Address sender() {
      return null;
    }
  }

  /** An echo's answer. */
  record Pong(Address destination, int n) implements Event {
    @Override
    public @Nullable Address sender() {
      return null;
    }
  }

  /** Answers each {@link Ping} with a {@link Pong} to {@code to}; fails on anything else. */
  static final class Echo implements EventProcessor {
    private final ActiveRef<?> to;

    Echo(ActiveRef<?> to) {
      this.to = to;
    }

    @Override
    public void process(Event event) {
      if (!(event instanceof Ping ping)) {
        throw new IllegalArgumentException("an echo takes a Ping, was " + event);
      }
      to.send(new Pong(to.address(), ping.n()));
    }
  }
}
