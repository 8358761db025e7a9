package org.armgals.presence;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.presence.PresenceEvent.Joined;
import org.armgals.presence.PresenceEvent.Left;
import org.armgals.presence.PresenceEvent.Lost;
import org.armgals.testkit.BrokerTest;
import org.armgals.testkit.TestBroker;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Presences on the testkit's embedded broker, on topics of each test's own. */
@BrokerTest
class PresenceTest {
  private static final long WAIT_SECONDS = 10;
  private static final Duration PERIOD = Duration.ofMillis(100);

  TestBroker broker;

  @BeforeEach
  void broker(TestBroker broker) {
    this.broker = broker;
  }

  /** What a listener heard, to wait on. */
  static final class Heard {
    final BlockingQueue<PresenceEvent> events = new LinkedBlockingQueue<>();

    PresenceEvent next() throws InterruptedException {
      PresenceEvent event = events.poll(WAIT_SECONDS, TimeUnit.SECONDS);
      assertThat(event).as("an event within %d s", WAIT_SECONDS).isNotNull();
      return event;
    }
  }

  private Presence.Builder builder(String prefix, String runtime, Heard heard) {
    return Presence.builder()
        .broker(broker.broker().inVmUrl())
        .prefix(broker.prefix() + "-" + prefix)
        .runtime(runtime)
        .period(PERIOD)
        .listener(heard.events::add);
  }

  @Test
  void runtimesThatBeatSeeEachOtherJoin() throws Exception {
    Heard heardByA = new Heard();
    Heard heardByB = new Heard();
    try (Presence a = builder("join", "a", heardByA).build();
        Presence b = builder("join", "b", heardByB).build()) {
      assertThat(heardByA.next()).isEqualTo(new Joined("b"));
      assertThat(heardByB.next()).isEqualTo(new Joined("a"));
      assertThat(a.peers()).containsExactly("b");
      assertThat(b.peers()).containsExactly("a");
    }
  }

  @Test
  void aRuntimeThatClosesItsPresenceIsHeardLeaving() throws Exception {
    Heard heardByA = new Heard();
    try (Presence a = builder("leave", "a", heardByA).build()) {
      Presence b = builder("leave", "b", new Heard()).build();
      assertThat(heardByA.next()).isEqualTo(new Joined("b"));

      b.close();

      assertThat(heardByA.next()).isEqualTo(new Left("b"));
      assertThat(a.peers()).isEmpty();
    }
  }

  @Test
  void aRuntimeSilentForMoreThanTheMissedBeatsIsLostAndJoinsAgainWhenItBeats() throws Exception {
    AtomicLong now = new AtomicLong();
    Heard heardByA = new Heard();
    PresenceImpl a =
        PresenceImpl.start(
            builder("lost", "a", heardByA).missedBeats(3).timeSource(now::get).validate(), false);
    PresenceImpl b = PresenceImpl.start(builder("lost", "b", new Heard()).validate(), false);
    try {
      assertThat(heardByA.next()).isEqualTo(new Joined("b"));

      now.addAndGet(PERIOD.toNanos() * 3);
      a.doWork();
      assertThat(heardByA.events).isEmpty();
      now.addAndGet(1);
      a.doWork();

      assertThat(heardByA.next()).isEqualTo(new Lost("b", PERIOD.multipliedBy(3).plusNanos(1)));
      assertThat(a.peers()).isEmpty();

      b.doWork();
      assertThat(heardByA.next()).isEqualTo(new Joined("b"));
    } finally {
      a.close();
      b.close();
    }
  }

  @Test
  void aListenerThatThrowsIsCountedAndTheOthersStillHear() throws Exception {
    Heard heard = new Heard();
    // The throwing listener comes first: listeners are called in order on one thread, so once
    // the second one has heard an event, the first one's failure on it has been counted.
    try (Presence a =
            Presence.builder()
                .broker(broker.broker().inVmUrl())
                .prefix(broker.prefix() + "-throw")
                .runtime("a")
                .period(PERIOD)
                .listener(
                    event -> {
                      throw new IllegalStateException("listener failure on purpose");
                    })
                .listener(heard.events::add)
                .build();
        Presence b = builder("throw", "b", new Heard()).build()) {
      assertThat(heard.next()).isEqualTo(new Joined(b.runtime()));
      assertThat(a.listenerFailures()).isEqualTo(1);
    }
  }

  @Test
  void settingsOutOfRangeAreRefusedWithTheValue() {
    assertThatThrownBy(() -> Presence.builder().runtime("a").build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("broker url");
    assertThatThrownBy(() -> Presence.builder().broker("vm://0").runtime(" ").build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("runtime must be a non-blank name, was ' '");
    assertThatThrownBy(
            () -> Presence.builder().broker("vm://0").runtime("a").period(Duration.ZERO).build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("period must be in [10 ms, 1 min], was PT0S");
    assertThatThrownBy(
            () -> Presence.builder().broker("vm://0").runtime("a").missedBeats(1).build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("missedBeats must be in [2, 1000], was 1");
    assertThatThrownBy(() -> Presence.builder().broker("vm://0").runtime("a").prefix("a b").build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'a b'");
  }
}
