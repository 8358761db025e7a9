package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicIntegerArray;
import javax.management.ObjectName;
import org.armgals.active.spi.Transport;
import org.junit.jupiter.api.Test;

/**
 * The runtime facade: lifecycle, figures, JMX, transport (docs/architecture.md, runtime semantics
 * 1, 5, 8, 9).
 */
class RuntimeTest {

  static final class Cell {
    int value;
    boolean open;
  }

  @Test
  void drainShutdownProcessesWhatIsQueuedIncludingWhatObjectsSendEachOther() {
    ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build();
    AtomicInteger done = new AtomicInteger();
    ActiveObject<Cell> b = rt.spawn(new Cell());
    ActiveObject<Cell> a = rt.spawn(new Cell());
    for (int i = 0; i < 10_000; i++) {
      a.send(c -> b.send(x -> done.incrementAndGet()));
    }
    assertThat(rt.shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(30))).isTrue();
    assertThat(done.get()).isEqualTo(10_000);
    assertThat(a.isStopped()).isTrue();
    assertThatThrownBy(() -> rt.spawn(new Cell()))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("shut down");
  }

  @Test
  void drainDoesNotWaitForGuardsThatNeverOpenAndFailsTheirFutures() {
    ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build();
    ActiveObject<Cell> cell = rt.spawn(new Cell());
    FutureValue<Integer> never = cell.callWhen(c -> c.open, c -> 1);
    // false: the guarded request had to be discarded
    assertThat(rt.shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(10))).isFalse();
    assertThatThrownBy(() -> never.getValue(Duration.ofSeconds(10)))
        .isInstanceOf(ObjectStoppedException.class);
  }

  @Test
  void cancelShutdownInterruptsObjectsWaitingByNecessity() throws Exception {
    ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build();
    ActiveObject<Cell> stuck = rt.spawn(new Cell());
    ActiveObject<Cell> waiter = rt.spawn(new Cell());
    CountDownLatch waiting = new CountDownLatch(1);
    FutureValue<Integer> outer =
        waiter.call(
            c -> {
              FutureValue<Integer> f = stuck.callWhen(x -> x.open, x -> 1);
              waiting.countDown();
              return f.getValue();
            });
    assertThat(waiting.await(10, TimeUnit.SECONDS)).isTrue();
    assertThat(rt.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(10))).isTrue();
    assertThatThrownBy(() -> outer.getValue(Duration.ofSeconds(10)))
        .isInstanceOf(RequestFailedException.class)
        .cause()
        .isInstanceOfAny(ObjectStoppedException.class, FutureInterruptedException.class);
  }

  @Test
  void dormantObjectsHoldNoPlatformThread() throws Exception {
    try (ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      int before = ManagementFactory.getThreadMXBean().getThreadCount();
      int n = 20_000;
      CountDownLatch ran = new CountDownLatch(n);
      List<ActiveObject<Cell>> cells = new ArrayList<>();
      for (int i = 0; i < n; i++) {
        ActiveObject<Cell> c = rt.spawn(new Cell());
        cells.add(c);
        c.send(x -> ran.countDown());
        c.sendWhen(x -> x.open, x -> x.value = 1); // stays queued: dormant, not running
      }
      assertThat(ran.await(30, TimeUnit.SECONDS)).isTrue();
      int after = ManagementFactory.getThreadMXBean().getThreadCount();
      assertThat(after - before).isLessThan(8);
      assertThat(rt.stats().objects()).isEqualTo(n);
      // The last objects may still be in the activation that ran their first event: until it
      // ends, the places it took count as queued. Once every object is idle, exactly the one
      // guarded event each is left.
      long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
      while (rt.stats().queuedEvents() != n && System.nanoTime() - deadline < 0) {
        Thread.onSpinWait();
      }
      assertThat(rt.stats().queuedEvents()).isEqualTo(n);
      assertThat(rt.stats().maxQueueDepth()).isEqualTo(1);
    }
  }

  @Test
  void figuresArePublishedOverJmx() throws Exception {
    ActiveRuntime rt = ActiveRuntime.builder().name("jmx-figures").build();
    {
      ActiveObject<Cell> cell = rt.spawn(new Cell());
      cell.send(
          c -> {
            throw new IllegalStateException("counted");
          });
      cell.call(c -> c.value).getValue(Duration.ofSeconds(10));
      var server = ManagementFactory.getPlatformMBeanServer();
      ObjectName name = new ObjectName("org.armgals:type=ActiveRuntime,name=\"jmx-figures\"");
      assertThat(server.getAttribute(name, "Objects")).isEqualTo(1L);
      assertThat(server.getAttribute(name, "Processed")).isEqualTo(2L);
      assertThat(server.getAttribute(name, "Failures")).isEqualTo(1L);
      assertThat(server.getAttribute(name, "Dropped")).isEqualTo(0L);
      assertThat(server.getAttribute(name, "Workers")).isInstanceOf(Integer.class);
      rt.close();
      assertThat(server.isRegistered(name)).isFalse();
    }
  }

  @Test
  void aFailingErrorHandlerDoesNotStopTheObject() {
    try (ActiveRuntime rt =
        ActiveRuntime.builder()
            .jmx(false)
            .errorHandler(
                (o, e, t) -> {
                  throw new IllegalStateException("handler broken");
                })
            .build()) {
      ActiveObject<Cell> cell = rt.spawn(new Cell());
      cell.send(
          c -> {
            throw new IllegalArgumentException("first");
          });
      cell.send(c -> c.value = 3);
      assertThat(cell.call(c -> c.value).getValue(Duration.ofSeconds(10))).isEqualTo(3);
    }
  }

  record Greeting(Address sender, Address destination, String text) implements Event {}

  static final class Greeter implements EventProcessor {
    final List<String> heard = new ArrayList<>();

    @Override
    public void process(Event event) {
      heard.add(((Greeting) event).text());
    }
  }

  @Test
  void eventsToAnotherRuntimeTravelThroughTheTransport() {
    Transport transport = Transport.inJvm();
    try (ActiveRuntime here =
            ActiveRuntime.builder().name("here").transport(transport).jmx(false).build();
        ActiveRuntime there =
            ActiveRuntime.builder().name("there").transport(transport).jmx(false).build()) {
      ActiveObject<Greeter> greeter = there.spawn(new Greeter());
      ActiveRef<Greeter> remote = here.ref(greeter.address());
      assertThat(remote).isNotSameAs(greeter);
      ActiveObject<Cell> sender = here.spawn(new Cell());
      sender.send(c -> remote.send(new Greeting(sender.address(), remote.address(), "hi")));
      sender.call(c -> c.value).getValue(Duration.ofSeconds(10));
      assertThat(greeter.call(g -> List.copyOf(g.heard)).getValue(Duration.ofSeconds(10)))
          .containsExactly("hi");
      assertThatThrownBy(() -> remote.send(g -> g.heard.clear()))
          .isInstanceOf(UnsupportedOperationException.class)
          .hasMessageContaining("another runtime");
      assertThat(here.<Cell>ref(sender.address())).isSameAs(sender);
    }
  }

  @Test
  void anObjectStoppedByItsOwnEventDiscardsTheRestOfItsBuffer() {
    try (ActiveRuntime rt = ActiveRuntime.builder().workers(1).jmx(false).build()) {
      ActiveObject<Cell> cell = rt.spawn(new Cell());
      CountDownLatch queued = new CountDownLatch(1);
      cell.send(
          c -> {
            queued.await();
            ActiveContext.current().orElseThrow().stop();
          });
      List<FutureValue<Integer>> after = new ArrayList<>();
      for (int i = 0; i < 10; i++) {
        after.add(cell.call(c -> ++c.value));
      }
      queued.countDown();
      for (FutureValue<Integer> f : after) {
        assertThatThrownBy(() -> f.getValue(Duration.ofSeconds(10)))
            .isInstanceOf(ObjectStoppedException.class);
      }
    }
  }

  @Test
  void objectsWokenByABusyActivationRunWhileItGoesOnButTheOneItsWorkerKeeps() throws Exception {
    // A worker keeps one object it woke for itself, to run next on the same core (another worker
    // may steal it); the others go to the shared queue, where the second worker takes them while
    // the activation, spinning, still holds the first worker.
    try (ActiveRuntime rt = ActiveRuntime.builder().workers(2).jmx(false).build()) {
      List<ActiveObject<Cell>> woken = new ArrayList<>();
      for (int i = 0; i < 4; i++) {
        woken.add(rt.spawn(new Cell()));
      }
      ActiveObject<Cell> busy = rt.spawn(new Cell());
      TimeSource time = ((RuntimeImpl) rt).timeSource();
      AtomicIntegerArray ran = new AtomicIntegerArray(woken.size());
      FutureValue<Integer> ranMeanwhile =
          busy.call(
              c -> {
                for (int i = 0; i < woken.size(); i++) {
                  int n = i;
                  woken.get(i).send(x -> ran.set(n, 1));
                }
                long deadline = time.nanoTime() + Duration.ofSeconds(10).toNanos();
                while (count(ran) < woken.size() - 1 && time.nanoTime() < deadline) {
                  Thread.onSpinWait(); // holds the worker: no park, no yield to the runtime
                }
                return count(ran);
              });
      assertThat(ranMeanwhile.getValue(Duration.ofSeconds(20)))
          .as("objects run while the activation that woke them went on; ran: %s", ran)
          .isGreaterThanOrEqualTo(woken.size() - 1);
      // And the one kept for later runs once the activation is over.
      for (ActiveObject<Cell> w : woken) {
        w.call(x -> 0).getValue(Duration.ofSeconds(10));
      }
      assertThat(count(ran)).as("ran: %s", ran).isEqualTo(woken.size());
    }
  }

  private static int count(AtomicIntegerArray flags) {
    int n = 0;
    for (int i = 0; i < flags.length(); i++) {
      n += flags.get(i);
    }
    return n;
  }

  @Test
  void aManualClockSteppedFromAnAsynchronousObjectDoesNotStarveTheWorkers() {
    try (ActiveRuntime rt = ActiveRuntime.builder().workers(1).jmx(false).build();
        ManualClock clock = Clock.manual(Duration.ofMillis(1))) {
      AtomicInteger cycles = new AtomicInteger();
      rt.spawn(
          (ReactiveCycle) instant -> cycles.incrementAndGet(), ObjectConfig.synchronous(clock));
      ActiveObject<Cell> driver = rt.spawn(new Cell());
      driver.signal(c -> clock.step(5)).touch(Duration.ofSeconds(10));
      assertThat(cycles.get()).isEqualTo(5);
    }
  }

  @Test
  void aWorkerEndedByAFatalErrorIsReplaced() {
    try (ActiveRuntime rt = ActiveRuntime.builder().workers(1).jmx(false).build()) {
      ActiveObject<Cell> doomed = rt.spawn(new Cell());
      doomed.send(
          c -> {
            throw new StackOverflowError("fatal, on purpose");
          });
      ActiveObject<Cell> other = rt.spawn(new Cell());
      assertThat(other.call(c -> 7).getValue(Duration.ofSeconds(10))).isEqualTo(7);
    }
  }

  @Test
  void badArgumentsAreRefusedNamingTheValue() {
    assertThatThrownBy(() -> ActiveRuntime.builder().workers(0))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("workers must be in [1, 1024], was 0");
    assertThatThrownBy(() -> ActiveRuntime.builder().name(" "))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("name must not be blank, was ' '");
    assertThatThrownBy(() -> new Address("r", 0))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("id must be >= 1, was 0");
    try (ActiveRuntime rt = ActiveRuntime.builder().name("lonely").jmx(false).build()) {
      assertThatThrownBy(() -> rt.ref(new Address("elsewhere", 1)))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("has no transport");
      assertThatThrownBy(() -> rt.ref(new Address("lonely", 99)))
          .isInstanceOf(ObjectStoppedException.class)
          .hasMessageContaining("lonely#99");
      assertThatThrownBy(() -> rt.shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(-1)))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("PT-1S");
    }
  }
}
