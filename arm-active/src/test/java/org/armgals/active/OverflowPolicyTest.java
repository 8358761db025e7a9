package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.armgals.active.spi.ObjectListener;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Bounded buffers and their overflow policies (docs/architecture.md, runtime semantics 4). A buffer
 * is filled deterministically with events whose guard is closed: they stay queued.
 */
class OverflowPolicyTest {

  static final class Gate {
    boolean open;
    final List<Integer> passed = new ArrayList<>();
  }

  /** Records drops, from whatever thread sends. */
  static final class Drops implements ObjectListener {
    final List<Event> dropped = new ArrayList<>();

    @Override
    public synchronized void onDropped(Address object, Event event, OverflowPolicy policy) {
      dropped.add(event);
    }

    synchronized int count() {
      return dropped.size();
    }
  }

  private static void fill(ActiveRef<Gate> gate, int n, int from) {
    for (int i = from; i < from + n; i++) {
      int v = i;
      gate.sendWhen(g -> g.open, g -> g.passed.add(v));
    }
  }

  private static ObjectConfig config(Harness h, int capacity, OverflowPolicy p, Drops drops) {
    return h.config().withCapacity(capacity).withOverflow(p).withListener(drops);
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void rejectPolicyThrowsNamingTheObjectAndCapacity(Mode mode) {
    try (Harness h = new Harness(mode)) {
      Drops drops = new Drops();
      ActiveObject<Gate> gate =
          h.runtime.spawn(new Gate(), config(h, 3, OverflowPolicy.reject(), drops));
      fill(gate, 3, 0);
      assertThat(gate.queueDepth()).isEqualTo(3);
      assertThatThrownBy(() -> fill(gate, 1, 3))
          .isInstanceOf(BufferFullException.class)
          .hasMessageContaining(gate.address().toString())
          .hasMessageContaining("capacity 3");
      assertThat(h.runtime.stats().rejected()).isEqualTo(1);
      assertThat(drops.count()).isZero();
    }
  }

  record Num(Address sender, Address destination, int value) implements Event {}

  /** Takes Num events while open; closed, they stay queued. */
  static final class NumGate implements EventProcessor {
    boolean open;
    final List<Integer> taken = new ArrayList<>();

    @Override
    public boolean isProcessable(Event event) {
      return open;
    }

    @Override
    public void process(Event event) {
      taken.add(((Num) event).value());
    }
  }

  private static void sendNums(ActiveRef<NumGate> gate, int from, int to) {
    for (int i = from; i < to; i++) {
      gate.send(new Num(gate.address(), gate.address(), i));
    }
  }

  private static List<Integer> droppedValues(Drops drops) {
    synchronized (drops) {
      return drops.dropped.stream().map(e -> ((Num) e).value()).toList();
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void dropNewestDropsTheArrivingEventAndTellsTheListener(Mode mode) {
    try (Harness h = new Harness(mode)) {
      Drops drops = new Drops();
      ActiveObject<NumGate> gate =
          h.runtime.spawn(new NumGate(), config(h, 3, OverflowPolicy.dropNewest(), drops));
      sendNums(gate, 0, 5);
      assertThat(droppedValues(drops)).containsExactly(3, 4);
      assertThat(gate.queueDepth()).isEqualTo(3);
      assertThat(h.runtime.stats().dropped()).isEqualTo(2);
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void dropOldestDropsTheOldestQueuedEventAndTellsTheListener(Mode mode) {
    try (Harness h = new Harness(mode)) {
      Drops drops = new Drops();
      ActiveObject<NumGate> gate =
          h.runtime.spawn(new NumGate(), config(h, 3, OverflowPolicy.dropOldest(), drops));
      sendNums(gate, 0, 5);
      assertThat(droppedValues(drops)).containsExactly(0, 1);
      assertThat(gate.queueDepth()).isEqualTo(3);
      assertThat(h.runtime.stats().dropped()).isEqualTo(2);
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void droppedSynchronizedRequestFailsItsFuture(Mode mode) {
    try (Harness h = new Harness(mode)) {
      Drops drops = new Drops();
      ActiveObject<Gate> gate =
          h.runtime.spawn(new Gate(), config(h, 1, OverflowPolicy.dropOldest(), drops));
      FutureValue<Boolean> first = gate.callWhen(g -> g.open, g -> true);
      fill(gate, 1, 0);
      assertThatThrownBy(() -> first.getValue(Harness.WAIT))
          .isInstanceOf(BufferFullException.class)
          .hasMessageContaining("dropped");
      assertThat(drops.count()).isEqualTo(1);
    }
  }

  @org.junit.jupiter.api.Test
  void blockPolicyHoldsTheSenderUntilThereIsRoom() throws Exception {
    try (Harness h = new Harness(Mode.ASYNCHRONOUS)) {
      ActiveObject<Gate> gate =
          h.runtime.spawn(
              new Gate(), config(h, 1, OverflowPolicy.block(Duration.ofSeconds(10)), new Drops()));
      CountDownLatch started = new CountDownLatch(1);
      CountDownLatch release = new CountDownLatch(1);
      gate.send(
          g -> {
            started.countDown();
            release.await();
            g.passed.add(0);
          });
      started.await();
      gate.send(g -> g.passed.add(1)); // fills the buffer of one
      CompletableFuture<Void> third =
          CompletableFuture.runAsync(
              () -> gate.send(g -> g.passed.add(2)), r -> Thread.ofVirtual().start(r));
      // The third send waits while the object is busy and its buffer full...
      assertThatThrownBy(() -> third.get(100, TimeUnit.MILLISECONDS))
          .isInstanceOf(java.util.concurrent.TimeoutException.class);
      // ...and gets in once the object takes its next event.
      release.countDown();
      third.get(10, TimeUnit.SECONDS);
      List<Integer> passed = h.get(gate.call(g -> List.copyOf(g.passed)));
      assertThat(passed).containsExactly(0, 1, 2);
    }
  }

  @org.junit.jupiter.api.Test
  void aSenderBlockedOnAnObjectThatIsStoppedGetsObjectStoppedAtOnce() throws Exception {
    try (Harness h = new Harness(Mode.ASYNCHRONOUS)) {
      ActiveObject<Gate> gate =
          h.runtime.spawn(
              new Gate(), config(h, 1, OverflowPolicy.block(Duration.ofMinutes(5)), new Drops()));
      CountDownLatch started = new CountDownLatch(1);
      CountDownLatch release = new CountDownLatch(1);
      gate.send(
          g -> {
            started.countDown();
            release.await();
          });
      started.await();
      gate.send(g -> g.passed.add(1)); // fills the buffer of one
      CompletableFuture<Void> blocked =
          CompletableFuture.runAsync(
              () -> gate.send(g -> g.passed.add(2)), r -> Thread.ofVirtual().start(r));
      assertThatThrownBy(() -> blocked.get(100, TimeUnit.MILLISECONDS))
          .isInstanceOf(java.util.concurrent.TimeoutException.class);
      gate.stop();
      assertThatThrownBy(() -> blocked.get(10, TimeUnit.SECONDS))
          .cause()
          .isInstanceOf(ObjectStoppedException.class);
      release.countDown();
    }
  }

  @org.junit.jupiter.api.Test
  void blockPolicyGivesUpAfterItsTimeout() {
    try (Harness h = new Harness(Mode.ASYNCHRONOUS)) {
      ActiveObject<Gate> gate =
          h.runtime.spawn(
              new Gate(), config(h, 1, OverflowPolicy.block(Duration.ofMillis(30)), new Drops()));
      fill(gate, 1, 0);
      assertThatThrownBy(() -> fill(gate, 1, 1))
          .isInstanceOf(BufferFullException.class)
          .hasMessageContaining("blocked for PT0.03S");
      assertThat(h.runtime.stats().rejected()).isEqualTo(1);
    }
  }

  @ParameterizedTest
  @ValueSource(ints = {0, -1, Integer.MIN_VALUE})
  void capacityBelowOneIsRefusedNamingTheValue(int capacity) {
    assertThatThrownBy(() -> ObjectConfig.asynchronous().withCapacity(capacity))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("capacity must be >= 1, was " + capacity);
  }

  @org.junit.jupiter.api.Test
  void reactiveObjectsNeverBlockTheirSenders() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1))) {
      assertThatThrownBy(
              () ->
                  ObjectConfig.synchronous(clock)
                      .withOverflow(OverflowPolicy.block(Duration.ofSeconds(1))))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("never blocks its sender");
    }
  }

  @org.junit.jupiter.api.Test
  void policiesParseFromTextAndUnknownOnesAreNamed() {
    assertThat(OverflowPolicy.parse("reject")).isEqualTo(OverflowPolicy.reject());
    assertThat(OverflowPolicy.parse("drop-newest")).isEqualTo(OverflowPolicy.dropNewest());
    assertThat(OverflowPolicy.parse("drop-oldest")).isEqualTo(OverflowPolicy.dropOldest());
    assertThat(OverflowPolicy.parse("block:PT5S"))
        .isEqualTo(OverflowPolicy.block(Duration.ofSeconds(5)));
    assertThatThrownBy(() -> OverflowPolicy.parse("drop-random"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'drop-random'")
        .hasMessageContaining("expected reject, drop-newest, drop-oldest or block:<duration>");
    assertThatThrownBy(() -> OverflowPolicy.parse("block:soon"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("bad duration");
    assertThatThrownBy(() -> OverflowPolicy.block(Duration.ofSeconds(-1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("PT-1S");
  }
}
