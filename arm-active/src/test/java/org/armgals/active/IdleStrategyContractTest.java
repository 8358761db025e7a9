package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.function.Supplier;
import java.util.stream.Stream;
import org.armgals.active.spi.IdleStrategy;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What every {@link IdleStrategy} of arm-active does with {@link IdleStrategy#spin()}: a bounded
 * number of steps that say "look again", then "block" until a reset, which starts a new wait.
 */
class IdleStrategyContractTest {

  /** A time that moves 100 ns at each read, so that a spin measured on it ends. */
  private static final class Ticking implements TimeSource {
    private long now;

    @Override
    public long nanoTime() {
      return now += 100;
    }
  }

  static Stream<Supplier<IdleStrategy>> strategies() {
    return Stream.of(
        () -> IdleStrategy.backoff(5, 2, Duration.ofNanos(1_000), Duration.ofNanos(1_000)),
        () -> new AdaptiveSpin(new Ticking(), 1_000, 1_000, 1_000));
  }

  private static int stepsUntilBlock(IdleStrategy s) {
    int steps = 0;
    while (s.spin()) {
      steps++;
      assertThat(steps).as("spin steps").isLessThan(10_000);
    }
    return steps;
  }

  @ParameterizedTest
  @MethodSource("strategies")
  void spinsABoundedNumberOfStepsThenSaysBlockUntilReset(Supplier<IdleStrategy> make) {
    IdleStrategy s = make.get();
    assertThat(stepsUntilBlock(s)).isPositive();
    for (int i = 0; i < 3; i++) {
      assertThat(s.spin()).isFalse();
    }
    s.reset();
    assertThat(s.spin()).isTrue();
  }

  @ParameterizedTest
  @MethodSource("strategies")
  void workDoneResetsLikeReset(Supplier<IdleStrategy> make) {
    IdleStrategy s = make.get();
    stepsUntilBlock(s);
    s.idle(1);
    assertThat(s.spin()).isTrue();
  }
}
