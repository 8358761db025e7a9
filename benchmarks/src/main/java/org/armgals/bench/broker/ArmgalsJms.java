package org.armgals.bench.broker;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.Request;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.JmsTransport;
import org.jspecify.annotations.Nullable;

/**
 * armgals over the same broker: two runtimes, each with its own {@link JmsTransport} (as two JVMs
 * would have), events from an object reference of one to an active object of the other, and
 * synchronized requests whose answers come back on {@code active/Future}; at least once, both types
 * are given {@link JmsTransport.Guarantee#AT_LEAST_ONCE}. Every run uses a topic prefix of its own,
 * so that runs never see each other's messages.
 */
final class ArmgalsJms implements BrokerImpl {
  private static final long TIMEOUT_SECONDS = 60;
  private static final AtomicInteger RUNS = new AtomicInteger();

  private final TimeSource time;

  ArmgalsJms(TimeSource time) {
    this.time = time;
  }

  /** A one-way event with its 64-byte payload. */
  record Payload(@Nullable Address sender, Address destination, byte[] bytes) implements Event {}

  /** A request whose answer is a 64-byte payload. */
  record Echo(@Nullable Address sender, Address destination, byte[] bytes)
      implements Request<byte[]> {}

  /** Counts events and opens a latch at the expected number; answers echoes. */
  static final class Sink implements EventProcessor {
    private final CountDownLatch done;
    private final int expected;
    private int received;

    Sink(int expected) {
      this.expected = expected;
      this.done = new CountDownLatch(1);
    }

    @Override
    public void process(Event event) {
      if (++received == expected) {
        done.countDown();
      }
    }

    @Override
    public Object answer(Request<?> request) {
      return ((Echo) request).bytes();
    }
  }

  @Override
  public String name() {
    return "armgals";
  }

  /** Two runtimes over the broker, closed together. */
  private record Pair(JmsTransport ta, JmsTransport tb, ActiveRuntime a, ActiveRuntime b)
      implements AutoCloseable {
    static Pair open(BenchBroker broker, Transport transport, Guarantee guarantee) {
      String prefix = "bench" + RUNS.incrementAndGet();
      JmsTransport ta = transport(broker, transport, guarantee, prefix);
      JmsTransport tb = transport(broker, transport, guarantee, prefix);
      return new Pair(ta, tb, runtime("a", ta), runtime("b", tb));
    }

    private static JmsTransport transport(
        BenchBroker broker, Transport transport, Guarantee guarantee, String prefix) {
      JmsTransport.Builder builder =
          JmsTransport.builder()
              .broker(
                  broker.url(transport, guarantee),
                  broker.user(guarantee),
                  broker.password(guarantee))
              .prefix(prefix)
              .allow(Payload.class, Echo.class);
      if (guarantee == Guarantee.ALO) {
        builder.guarantee(JmsTransport.Guarantee.AT_LEAST_ONCE, Payload.class, Echo.class);
      }
      return builder.build();
    }

    private static ActiveRuntime runtime(String name, JmsTransport transport) {
      return ActiveRuntime.builder().name(name).jmx(false).transport(transport).build();
    }

    @Override
    public void close() {
      a.close();
      b.close();
      ta.close();
      tb.close();
    }
  }

  @Override
  public double events(BenchBroker broker, Transport transport, Guarantee guarantee, int messages)
      throws Exception {
    try (Pair pair = Pair.open(broker, transport, guarantee)) {
      Sink sink = new Sink(messages);
      ActiveObject<Sink> receiver = pair.b().spawn(sink);
      ActiveRef<Sink> remote = pair.a().ref(receiver.address());
      byte[] payload = new byte[BrokerBench.PAYLOAD_BYTES];
      long start = time.nanoTime();
      for (int i = 0; i < messages; i++) {
        remote.send(new Payload(null, receiver.address(), payload));
      }
      if (!sink.done.await(TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
        throw new IllegalStateException(
            "armgals events: not all " + messages + " arrived within " + TIMEOUT_SECONDS + " s");
      }
      return messages / ((time.nanoTime() - start) / 1e9);
    }
  }

  @Override
  public long[] futureRoundTrips(
      BenchBroker broker, Transport transport, Guarantee guarantee, int requests) throws Exception {
    try (Pair pair = Pair.open(broker, transport, guarantee)) {
      ActiveObject<Sink> servant = pair.b().spawn(new Sink(Integer.MAX_VALUE));
      ActiveRef<Sink> remote = pair.a().ref(servant.address());
      byte[] payload = new byte[BrokerBench.PAYLOAD_BYTES];
      long[] nanos = new long[requests];
      for (int i = 0; i < requests; i++) {
        long start = time.nanoTime();
        byte[] answer =
            remote
                .ask(new Echo(null, servant.address(), payload))
                .getValue(java.time.Duration.ofSeconds(TIMEOUT_SECONDS));
        nanos[i] = time.nanoTime() - start;
        if (answer.length != payload.length) {
          throw new IllegalStateException(
              "armgals futurertt: request " + i + " got " + answer.length + " bytes back");
        }
      }
      return nanos;
    }
  }
}
