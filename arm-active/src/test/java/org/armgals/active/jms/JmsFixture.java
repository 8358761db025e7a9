package org.armgals.active.jms;

import java.io.IOException;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.Request;
import org.armgals.active.Selectable;
import org.jspecify.annotations.Nullable;

/** Event types and helpers shared by the JMS transport's tests. */
final class JmsFixture {
  private JmsFixture() {}

  static final Duration WAIT = Duration.ofSeconds(10);

  enum Level {
    LOW,
    HIGH
  }

  record Reading(String sensor, double value, Level level, List<Integer> samples) {}

  record Ping(@Nullable Address sender, Address destination, long n) implements Event {}

  record Energy(@Nullable Address sender, Address destination, long n, int energy)
      implements Selectable {
    @Override
    public Map<String, ?> selectorProperties() {
      return Map.of("energy", energy);
    }
  }

  record Measure(
      @Nullable Address sender,
      Address destination,
      Reading reading,
      Map<String, Long> counts,
      byte[] raw)
      implements Event {}

  record Sum(@Nullable Address sender, Address destination, int a, int b)
      implements Request<Integer> {}

  record Explode(@Nullable Address sender, Address destination, String why)
      implements Request<String> {}

  record Echo(@Nullable Address sender, Address destination, Reading reading)
      implements Request<Reading> {}

  /** Not on any allow-list. */
  record Secret(@Nullable Address sender, Address destination, String text) implements Event {}

  static final Class<?>[] ALLOWED = {
    Level.class,
    Reading.class,
    Ping.class,
    Energy.class,
    Measure.class,
    Sum.class,
    Explode.class,
    Echo.class
  };

  /** Collects what it receives, answers sums, echoes and explodes. */
  static final class Sink implements EventProcessor {
    final List<Event> events = new CopyOnWriteArrayList<>();

    @Override
    public void process(Event event) {
      events.add(event);
    }

    @Override
    public @Nullable Object answer(Request<?> request) {
      return switch (request) {
        case Sum s -> s.a() + s.b();
        case Echo e -> e.reading();
        case Explode x -> throw new IllegalStateException(x.why());
        default -> throw new IllegalArgumentException("unexpected " + request);
      };
    }

    long count() {
      return events.size();
    }
  }

  static JmsTransport.Builder transport(String url) {
    return JmsTransport.builder().broker(url).allow(ALLOWED);
  }

  static ActiveRuntime runtime(String name, JmsTransport t) {
    return ActiveRuntime.builder().name(name).workers(2).jmx(false).transport(t).build();
  }

  static int freePort() {
    try (ServerSocket s = new ServerSocket(0)) {
      return s.getLocalPort();
    } catch (IOException e) {
      throw new IllegalStateException(e);
    }
  }
}
