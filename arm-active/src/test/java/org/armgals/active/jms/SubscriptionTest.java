package org.armgals.active.jms;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.Filter;
import org.armgals.active.jms.JmsFixture.Energy;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Published events, filtered subscriptions and filter swaps (docs/architecture.md, runtime
 * semantics 6).
 */
class SubscriptionTest {
  static final Address BATTERY = new Address("robot", 1);
  static EmbeddedBroker broker;

  @BeforeAll
  static void startBroker() {
    broker = EmbeddedBroker.start();
  }

  @AfterAll
  static void stopBroker() {
    broker.close();
  }

  static JmsTransport transport(String prefix) {
    return JmsFixture.transport(broker.inVmUrl()).prefix(prefix).build();
  }

  @Test
  void aSubscriptionGetsWhatItsFilterTakesLocallyAndThroughTheBroker() {
    try (JmsTransport publisher = transport("filter");
        JmsTransport remote = transport("filter")) {
      List<Event> here = new CopyOnWriteArrayList<>();
      List<Event> there = new CopyOnWriteArrayList<>();
      Filter low = Filter.selector("kind = 'Energy' AND energy < 20");
      publisher.subscribe(JmsTransport.Topic.BMETA, low, here::add);
      remote.subscribe(JmsTransport.Topic.BMETA, low, there::add);
      for (int i = 0; i < 40; i++) {
        publisher.publish(JmsTransport.Topic.BMETA, new Energy(BATTERY, BATTERY, i, i));
      }
      HostileInputTest.await(() -> there.size() >= 20, JmsFixture.WAIT);
      assertThat(here).hasSize(20).allMatch(e -> ((Energy) e).energy() < 20);
      assertThat(there).containsExactlyElementsOf(here);
      // another topic is another subscription
      publisher.publish(JmsTransport.Topic.SMETA, new Energy(BATTERY, BATTERY, 99, 1));
      publisher.publish(JmsTransport.Topic.BMETA, new Energy(BATTERY, BATTERY, 100, 1));
      HostileInputTest.await(() -> there.size() >= 21, JmsFixture.WAIT);
      assertThat(((Energy) there.get(20)).n()).isEqualTo(100);
    }
  }

  @Test
  void subscribingToTheFutureTopicIsRefused() {
    try (JmsTransport t = transport("refuse")) {
      assertThatThrownBy(() -> t.subscribe(JmsTransport.Topic.FUTURE, Filter.ALL, e -> {}))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("FUTURE");
    }
  }

  /**
   * The paper's battery example under load: a subscriber swaps between "energy below 20" and
   * "energy in [10, 30)" while events stream in. Every event both filters take arrives exactly
   * once; no event arrives twice; none arrives that neither filter takes.
   */
  @ParameterizedTest(name = "subscriber {0}")
  @ValueSource(strings = {"local", "remote"})
  void aFilterSwappedUnderLoadLosesAndDuplicatesNothing(String where) throws Exception {
    try (JmsTransport publisher = transport("swap-" + where);
        JmsTransport other = transport("swap-" + where)) {
      JmsTransport subscriber = where.equals("local") ? publisher : other;
      ConcurrentHashMap<Long, AtomicInteger> got = new ConcurrentHashMap<>();
      AtomicInteger outside = new AtomicInteger();
      Filter low = Filter.selector("energy < 20");
      Filter high = Filter.selector("energy >= 10 AND energy < 30");
      Subscription sub =
          subscriber.subscribe(
              JmsTransport.Topic.BMETA,
              low,
              e -> {
                Energy en = (Energy) e;
                if (en.energy() >= 30) {
                  outside.incrementAndGet();
                }
                got.computeIfAbsent(en.n(), k -> new AtomicInteger()).incrementAndGet();
              });
      int n = 20_000;
      Thread load =
          Thread.ofPlatform()
              .start(
                  () -> {
                    for (int i = 0; i < n; i++) {
                      publisher.publish(
                          JmsTransport.Topic.BMETA, new Energy(BATTERY, BATTERY, i, i % 40));
                    }
                  });
      int swaps = 0;
      while (load.isAlive() && swaps < 20) {
        sub.swap(swaps % 2 == 0 ? high : low);
        swaps++;
      }
      load.join();
      List<Long> both = new ArrayList<>();
      for (long i = 0; i < n; i++) {
        int energy = (int) (i % 40);
        if (energy >= 10 && energy < 20) {
          both.add(i);
        }
      }
      HostileInputTest.await(
          () -> both.stream().allMatch(got::containsKey), Duration.ofSeconds(30));
      assertThat(swaps).isPositive();
      assertThat(got.values()).allMatch(c -> c.get() == 1);
      assertThat(got.keySet()).allMatch(i -> i < n);
      assertThat(outside).hasValue(0);
      assertThat(sub.filter()).isEqualTo(swaps % 2 == 0 ? low : high);
    }
  }
}
