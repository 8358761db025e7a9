package org.armgals.active.jms;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.armgals.active.Address;
import org.armgals.active.Filter;
import org.armgals.active.FilterContractTest;
import org.armgals.active.Selectable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.provider.Arguments;

/**
 * {@link FilterContractTest}'s table once more, evaluated by the broker: every selector is a
 * subscription of another transport, and the broker must let through exactly what {@link
 * Filter#matches} takes (docs/architecture.md, runtime semantics 6: a filter means the same on both
 * paths).
 */
class BrokerFilterContractTest {
  static final Address BATTERY = new Address("robot", 1);

  /** The battery's state, with the table's properties (but kind, which is the class name). */
  record StateEvent(Address sender, Address destination) implements Selectable {
    @Override
    public Map<String, ?> selectorProperties() {
      Map<String, Object> p = new HashMap<>(FilterContractTest.BATTERY);
      p.remove("kind");
      p.remove("seq"); // reserved: the transport's own sequence number
      return p;
    }
  }

  /** Sent after the battery's event: every subscription takes it, so it closes the wait. */
  record Last(Address sender, Address destination) implements Selectable {
    @Override
    public Map<String, ?> selectorProperties() {
      return Map.of("last", true);
    }
  }

  @Test
  void theBrokerTakesWhatFilterMatchesTakes() throws Exception {
    List<String> selectors = new ArrayList<>();
    for (Arguments a : FilterContractTest.selectors().toList()) {
      String s = (String) a.get()[0];
      if (!s.contains("seq")) {
        selectors.add(s);
      }
    }
    try (EmbeddedBroker broker = EmbeddedBroker.start();
        JmsTransport publisher =
            JmsTransport.builder()
                .broker(broker.inVmUrl())
                .allow(StateEvent.class, Last.class)
                .build();
        JmsTransport subscriber =
            JmsTransport.builder()
                .broker(broker.inVmUrl())
                .allow(StateEvent.class, Last.class)
                .build()) {
      Map<String, Boolean> onBroker = new ConcurrentHashMap<>();
      CountDownLatch done = new CountDownLatch(selectors.size());
      for (String s : selectors) {
        subscriber.subscribe(
            JmsTransport.Topic.BMETA,
            Filter.selector("(" + s + ") OR last = TRUE"),
            e -> {
              if (e instanceof StateEvent) {
                onBroker.put(s, true);
              } else {
                onBroker.putIfAbsent(s, false);
                done.countDown();
              }
            });
      }
      StateEvent battery = new StateEvent(BATTERY, BATTERY);
      publisher.publish(JmsTransport.Topic.BMETA, battery);
      publisher.publish(JmsTransport.Topic.BMETA, new Last(BATTERY, BATTERY));
      assertThat(done.await(10, TimeUnit.SECONDS)).isTrue();

      Map<String, Object> local = new HashMap<>(battery.selectorProperties());
      local.put("kind", "StateEvent");
      local.put("sender", BATTERY.toString());
      local.put("destination", BATTERY.toString());
      Map<String, Boolean> inMemory = new HashMap<>();
      for (String s : selectors) {
        inMemory.put(s, Filter.selector(s).matches(local));
      }
      assertThat(onBroker).isEqualTo(inMemory);
      assertThat(inMemory).containsValue(true).containsValue(false);
    }
  }
}
