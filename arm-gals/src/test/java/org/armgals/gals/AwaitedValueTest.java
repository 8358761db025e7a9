package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Futures as stimuli (paper §5.2): active wait, time-outs, cancellation with their reaction. */
class AwaitedValueTest {
  private final ActiveRuntime runtime = Fixtures.runtime("await", 2);
  private final Island here =
      Island.builder("here", runtime).period(Duration.ofMillis(10)).tracing(true).build();
  private final Island there =
      Island.builder("there", runtime).period(Duration.ofMillis(10)).build();

  @AfterEach
  void close() {
    here.close();
    there.close();
    runtime.close();
  }

  static final class Asker {
    @Nullable AwaitedValue<Integer> awaited;
    final List<String> log = new ArrayList<>();
    int otherWork;
  }

  private ReactiveEntity<Asker> askerOf(ReactiveEntity<Integer> target, Asker asker, Duration t) {
    ReactiveEntity<Asker> e =
        here.spawn(
            "asker",
            asker,
            c -> {
              if (c.state().awaited == null) {
                c.state().awaited = c.call(target, x -> x * 2, t);
              }
              c.state().log.add(c.instant() + ":" + c.state().awaited.status());
            });
    e.addReaction("other", c -> c.state().otherWork++);
    return e;
  }

  @Test
  void unansweredValueTimesOutAfterItsTimeoutWhileOtherReactionsGoOn() {
    ReactiveEntity<Integer> silent = there.spawn("silent", 21, c -> {}); // never stepped yet
    Asker asker = new Asker();
    askerOf(silent, asker, Duration.ofMillis(25)); // 2.5 periods: 3 instants

    here.step(5);
    there.step(); // answers now, too late
    here.step();

    assertThat(asker.log)
        .containsExactly(
            "1:PENDING", "2:PENDING", "3:PENDING", "4:TIMED_OUT", "5:TIMED_OUT", "6:TIMED_OUT");
    assertThat(asker.otherWork).isEqualTo(6);
    assertThat(here.trace()).contains("here 4 asker a value awaited by main timed out");
    assertThatThrownBy(() -> asker.awaited.value())
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("TIMED_OUT");
  }

  @Test
  void answerWithinTheTimeoutIsAvailable() {
    ReactiveEntity<Integer> target = there.spawn("target", 21, c -> {});
    Asker asker = new Asker();
    askerOf(target, asker, Duration.ofMillis(30));

    here.step();
    there.step();
    here.step();

    assertThat(asker.log).containsExactly("1:PENDING", "2:AVAILABLE");
    assertThat(asker.awaited.value()).isEqualTo(42);
  }

  @Test
  void removingTheReactionThatAwaitsAValueCancelsIt() {
    ReactiveEntity<Integer> target = there.spawn("target", 21, c -> {});
    Asker asker = new Asker();
    ReactiveEntity<Asker> e = askerOf(target, asker, Duration.ofSeconds(1));

    here.step();
    e.removeReaction("main");
    here.step();
    there.step(); // the answer comes after the cancellation
    here.step();

    assertThat(asker.awaited.status()).isEqualTo(AwaitedValue.Status.CANCELLED);
    assertThat(asker.log).containsExactly("1:PENDING");
    assertThat(asker.otherWork).isEqualTo(3);
    assertThat(here.trace()).contains("here 2 asker cancelled a value awaited by main");
  }

  @Test
  void failedQueryGivesAFailedValueWithItsCause() {
    ReactiveEntity<Integer> target = there.spawn("target", 21, c -> {});
    Asker asker = new Asker();
    here.spawn(
        "asker",
        asker,
        c -> {
          if (c.state().awaited == null) {
            c.state().awaited =
                c.call(
                    target,
                    x -> {
                      throw new ArithmeticException("no answer for " + x);
                    },
                    Duration.ofSeconds(1));
          }
        });

    here.step();
    there.step();
    here.step();

    assertThat(asker.awaited.status()).isEqualTo(AwaitedValue.Status.FAILED);
    assertThat(asker.awaited.failure())
        .get()
        .isInstanceOf(ArithmeticException.class)
        .extracting(Throwable::getMessage)
        .isEqualTo("no answer for 21");
  }

  @Test
  void nonPositiveTimeoutIsRefusedNamingIt() {
    ReactiveEntity<Integer> target = there.spawn("target", 21, c -> {});
    List<Throwable> thrown = new ArrayList<>();
    here.spawn(
        "asker",
        0,
        c -> {
          try {
            c.call(target, x -> x, Duration.ZERO);
          } catch (IllegalArgumentException e) {
            thrown.add(e);
          }
        });
    here.step();
    assertThat(thrown)
        .singleElement()
        .extracting(Throwable::getMessage)
        .isEqualTo("timeout must be > 0, was PT0S");
  }
}
