package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Two islands with their own periods, composed asynchronously (GALS). */
class IslandPairTest {
  private final ActiveRuntime runtime = Fixtures.runtime("pair", 2);
  private final Island fast =
      Island.builder("fast", runtime).period(Duration.ofMillis(10)).tracing(true).build();
  private final Island slow =
      Island.builder("slow", runtime).period(Duration.ofMillis(20)).tracing(true).build();

  @AfterEach
  void close() {
    fast.close();
    slow.close();
    runtime.close();
  }

  static final class Sensor {
    int reading;
  }

  static final class Controller {
    final List<List<Object>> inputs = new ArrayList<>();
    final List<String> answers = new ArrayList<>();
    @org.jspecify.annotations.Nullable AwaitedValue<Integer> asked;
  }

  @Test
  void eventFromAnotherIslandArrivesAtTheReceiversNextRelease() {
    Controller controller = new Controller();
    ReactiveEntity<Controller> c =
        slow.spawn("controller", controller, k -> k.state().inputs.add(k.inputs()));
    fast.spawn(
        "sensor",
        new Sensor(),
        k -> {
          k.state().reading = (int) k.instant() * 10;
          k.emit(c, k.state().reading);
        });

    fast.step(); // emits 10
    slow.step(); // sees 10
    fast.step(); // emits 20
    fast.step(); // emits 30
    slow.step(); // sees both, in the sensor's send order
    slow.step(); // sees nothing new

    assertThat(controller.inputs).containsExactly(List.of(10), List.of(20, 30), List.of());
  }

  @Test
  void futureAcrossIslandsIsAvailableAtTheFirstReleaseAfterTheAnswer() {
    Controller controller = new Controller();
    ReactiveEntity<Sensor> s = fast.spawn("sensor", new Sensor(), k -> k.state().reading = 42);
    slow.spawn(
        "controller",
        controller,
        k -> {
          Controller st = k.state();
          if (st.asked == null) {
            st.asked = k.call(s, x -> x.reading + 1, Duration.ofSeconds(1));
          }
          st.answers.add(k.instant() + ":" + st.asked.status());
          if (!st.asked.isPending()) {
            st.answers.add("value " + st.asked.value());
          }
        });

    fast.step(); // reading = 42
    slow.step(); // 1: asks
    slow.step(); // 2: the sensor has not taken the request: still pending, the cycle goes on
    fast.step(); // the sensor answers 43
    slow.step(); // 3: the answer is there

    assertThat(controller.answers)
        .containsExactly("1:PENDING", "2:PENDING", "3:AVAILABLE", "value 43");
  }
}
