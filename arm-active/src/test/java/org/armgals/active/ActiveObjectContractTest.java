package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The rules every active object keeps, in both modes (docs/architecture.md, runtime semantics 1, 2,
 * 8).
 */
class ActiveObjectContractTest {

  /** Records what it is asked to do, in order. */
  static final class Recorder {
    final List<String> seen = new ArrayList<>();

    void add(String s) {
      seen.add(s);
    }

    int size() {
      return seen.size();
    }
  }

  /** A bounded buffer of one slot, the paper's guarded example. */
  static final class Slot {
    @Nullable String item;

    boolean empty() {
      return item == null;
    }
  }

  record Note(@Nullable Address sender, Address destination, String text) implements Event {}

  static final class NoteTaker implements EventProcessor {
    final List<String> notes = new ArrayList<>();
    boolean open = true;

    @Override
    public boolean isProcessable(Event event) {
      return open;
    }

    @Override
    public void process(Event event) {
      if (event instanceof Note n) {
        notes.add(n.text());
      }
    }
  }

  private static List<String> seen(Harness h, ActiveRef<Recorder> r) {
    List<String> seen = h.get(r.call(x -> List.copyOf(x.seen)));
    return seen;
  }

  private static List<String> notes(Harness h, ActiveRef<NoteTaker> t) {
    List<String> notes = h.get(t.call(s -> List.copyOf(s.notes)));
    return notes;
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void eventsFromOneSenderAreProcessedInSendOrder(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      List<String> expected = new ArrayList<>();
      for (int i = 0; i < 1_000; i++) {
        String s = "e" + i;
        expected.add(s);
        r.send(x -> x.add(s));
      }
      assertThat(seen(h, r)).isEqualTo(expected);
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void guardedEventWaitsUntilStateAllowsIt(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Slot> slot = h.spawn(new Slot());
      FutureValue<@Nullable String> taken =
          slot.callWhen(
              s -> !s.empty(),
              s -> {
                String v = s.item;
                s.item = null;
                return v;
              });
      // Not processable yet: it stays queued while the object goes on with other events.
      assertThat(h.get(slot.call(Slot::empty))).isTrue();
      assertThat(taken.isDone()).isFalse();
      slot.sendWhen(Slot::empty, s -> s.item = "apple");
      assertThat(h.get(taken)).isEqualTo("apple");
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void guardedEventIsOvertakenByLaterProcessableEvents(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      r.sendWhen(x -> x.size() >= 2, x -> x.add("guarded"));
      r.send(x -> x.add("first"));
      r.send(x -> x.add("second"));
      List<String> seen = h.get(r.callWhen(x -> x.size() == 3, x -> List.copyOf(x.seen)));
      assertThat(seen).containsExactly("first", "second", "guarded");
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void dataEventsGoToTheEventProcessorAndRespectItsGuard(Mode mode) {
    try (Harness h = new Harness(mode)) {
      NoteTaker taker = new NoteTaker();
      taker.open = false;
      ActiveObject<NoteTaker> t = h.spawn(taker);
      t.send(new Note(null, t.address(), "hello"));
      assertThat(notes(h, t)).isEmpty();
      t.send(s -> s.open = true);
      assertThat(notes(h, t)).containsExactly("hello");
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void dataEventAddressedElsewhereIsRefusedNamingBothAddresses(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<NoteTaker> a = h.spawn(new NoteTaker());
      ActiveObject<NoteTaker> b = h.spawn(new NoteTaker());
      assertThatThrownBy(() -> a.send(new Note(null, b.address(), "x")))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining(a.address().toString())
          .hasMessageContaining(b.address().toString());
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void dataEventToAServantThatTakesNoneFailsToTheErrorHandler(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      r.send(new Note(null, r.address(), "lost?"));
      assertThat(h.get(r.call(Recorder::size))).isZero();
      assertThat(h.errors())
          .singleElement()
          .satisfies(e -> assertThat(e).hasMessageContaining("takes no data events"));
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void failureInServantCompletesTheFutureWithTheCauseAndTheObjectGoesOn(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      FutureValue<Integer> bad =
          r.call(
              x -> {
                throw new IllegalStateException("boom");
              });
      if (mode == Mode.SYNCHRONOUS) {
        h.clock.stepUntil(bad::isDone, 10);
      }
      assertThatThrownBy(() -> bad.getValue(Harness.WAIT))
          .isInstanceOf(RequestFailedException.class)
          .hasMessageContaining(r.address().toString())
          .cause()
          .isInstanceOf(IllegalStateException.class)
          .hasMessage("boom");
      r.send(x -> x.add("after"));
      assertThat(h.get(r.call(Recorder::size))).isEqualTo(1);
      assertThat(h.errors()).singleElement().isInstanceOf(IllegalStateException.class);
      assertThat(h.runtime.stats().failures()).isEqualTo(1);
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void listenerHearsOfEveryFailureWithItsEvent(Mode mode) {
    try (Harness h = new Harness(mode)) {
      List<String> heard = new ArrayList<>();
      ObjectConfig config =
          h.config()
              .withListener(
                  new org.armgals.active.spi.ObjectListener() {
                    @Override
                    public synchronized void onFailed(
                        Address object, @Nullable Event event, Throwable error) {
                      heard.add(object + ":" + error.getMessage());
                    }
                  });
      ActiveObject<Recorder> r = h.runtime.spawn(new Recorder(), config);
      r.send(
          x -> {
            throw new IllegalArgumentException("nope");
          });
      h.get(r.call(Recorder::size));
      synchronized (heard) {
        assertThat(heard).containsExactly(r.address() + ":nope");
      }
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void aGuardThatThrowsFailsItsRequestWithoutRunningIt(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      FutureValue<String> f =
          r.callWhen(
              x -> {
                throw new IllegalStateException("guard broke");
              },
              x -> {
                x.add("ran");
                return "ran anyway";
              });
      if (mode == Mode.SYNCHRONOUS) {
        h.clock.stepUntil(f::isDone, 10);
      }
      assertThatThrownBy(() -> f.getValue(Harness.WAIT))
          .isInstanceOf(RequestFailedException.class)
          .rootCause()
          .hasMessage("guard broke");
      assertThat(h.get(r.call(Recorder::size))).isZero();
      assertThat(h.errors()).hasSize(1);
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void sendToAStoppedObjectThrowsNamingIt(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      r.stop();
      assertThat(r.isStopped()).isTrue();
      assertThatThrownBy(() -> r.send(x -> x.add("late")))
          .isInstanceOf(ObjectStoppedException.class)
          .hasMessageContaining(r.address().toString());
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void stoppingFailsTheFuturesOfQueuedRequests(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Slot> slot = h.spawn(new Slot());
      FutureValue<Boolean> never = slot.callWhen(s -> !s.empty(), s -> true);
      slot.stop();
      assertThatThrownBy(() -> never.getValue(Harness.WAIT))
          .isInstanceOf(ObjectStoppedException.class)
          .hasMessageContaining(slot.address().toString());
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void methodRequestSubclassesRunWithTheirGuard(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Slot> slot = h.spawn(new Slot());
      final class Take extends SynchronizedMethodRequest<Slot, String> {
        @Override
        protected boolean guard(Slot s) {
          return !s.empty();
        }

        @Override
        protected String invoke(Slot s) {
          String v = java.util.Objects.requireNonNull(s.item);
          s.item = null;
          return v;
        }
      }
      final class Put extends MethodRequest<Slot> {
        @Override
        protected void invoke(Slot s) {
          s.item = "pear";
        }
      }
      FutureValue<String> take = slot.call(new Take());
      Put put = new Put();
      slot.send(put);
      assertThat(h.get(take)).isEqualTo("pear");
      assertThat(put.destination()).isEqualTo(slot.address());
      assertThatThrownBy(() -> slot.send(put))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("already sent");
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void senderIsTheObjectWhoseCodeSent(Mode mode) {
    try (Harness h = new Harness(mode)) {
      NoteTaker taker = new NoteTaker();
      ActiveObject<NoteTaker> t = h.spawn(taker);
      List<@Nullable Address> senders = new ArrayList<>();
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      class Probe extends MethodRequest<NoteTaker> {
        @Override
        protected void invoke(NoteTaker s) {
          senders.add(sender());
        }
      }
      r.send(x -> t.send(new Probe()));
      t.send(new Probe());
      h.awaitUntil(t, () -> senders.size() == 2);
      assertThat(senders).containsExactlyInAnyOrder(r.address(), null);
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void nullArgumentsAreRefusedByName(Mode mode) {
    try (Harness h = new Harness(mode)) {
      ActiveObject<Recorder> r = h.spawn(new Recorder());
      assertThatThrownBy(() -> r.send((ServantAction<Recorder>) null))
          .isInstanceOf(NullPointerException.class)
          .hasMessage("action");
      assertThatThrownBy(() -> r.send((Event) null))
          .isInstanceOf(NullPointerException.class)
          .hasMessage("event");
      assertThatThrownBy(() -> h.runtime.spawn(null))
          .isInstanceOf(NullPointerException.class)
          .hasMessage("servant");
    }
  }

  @ParameterizedTest
  @EnumSource(Mode.class)
  void manyObjectsEachProcessTheirOwnEventsConcurrently(Mode mode) throws Exception {
    try (Harness h = new Harness(mode)) {
      int n = 2_000;
      CountDownLatch done = new CountDownLatch(n);
      List<ActiveObject<Recorder>> all = new ArrayList<>();
      for (int i = 0; i < n; i++) {
        ActiveObject<Recorder> r = h.spawn(new Recorder());
        all.add(r);
        r.send(x -> x.add("one"));
        r.send(
            x -> {
              x.add("two");
              done.countDown();
            });
      }
      if (mode == Mode.SYNCHRONOUS) {
        h.clock.step();
      }
      assertThat(done.await(10, java.util.concurrent.TimeUnit.SECONDS)).isTrue();
      for (ActiveObject<Recorder> r : all) {
        assertThat(seen(h, r)).containsExactly("one", "two");
      }
    }
  }
}
