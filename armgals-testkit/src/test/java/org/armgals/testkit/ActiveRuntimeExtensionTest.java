package org.armgals.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.armgals.testkit.Messages.Echo;
import org.armgals.testkit.Messages.Ping;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.platform.testkit.engine.Events;

/** The runtime extension, run on fixture classes as a user's build runs them. */
class ActiveRuntimeExtensionTest {

  /** What the fixtures were given, to look at once they ran. */
  static final List<Object> GIVEN = new ArrayList<>();

  @BeforeEach
  void forget() {
    GIVEN.clear();
  }

  @ActiveTest
  static class TwoTests {
    ActiveRuntime before;

    @BeforeEach
    void setUp(ActiveRuntime runtime) {
      before = runtime;
    }

    @Test
    void first(ActiveRuntime runtime) {
      GIVEN.add(before == runtime);
      GIVEN.add(runtime);
    }

    @Test
    void second(ActiveRuntime runtime) {
      GIVEN.add(before == runtime);
      GIVEN.add(runtime);
    }
  }

  @Test
  void eachTestHasARuntimeOfItsOwnSharedWithItsBeforeEachAndShutDownAfterIt() {
    Fixtures.run(TwoTests.class).assertStatistics(s -> s.succeeded(2).failed(0));
    assertThat(GIVEN).hasSize(4);
    assertThat(GIVEN.get(0)).isEqualTo(true);
    assertThat(GIVEN.get(2)).isEqualTo(true);
    ActiveRuntime first = (ActiveRuntime) GIVEN.get(1);
    ActiveRuntime second = (ActiveRuntime) GIVEN.get(3);
    assertThat(first).isNotSameAs(second);
    assertThat(List.of(first.name(), second.name()))
        .as("named after their tests")
        .allMatch(n -> n.matches("(first|second)-\\d+"));
    assertThatThrownBy(() -> first.spawn(new Object()))
        .as("shut down after the test")
        .isInstanceOf(IllegalStateException.class);
    assertThatThrownBy(() -> second.spawn(new Object())).isInstanceOf(IllegalStateException.class);
  }

  @ActiveTest(manualClock = true, periodMillis = 20)
  static class OnAManualClock {
    @Test
    void stepped(ActiveRuntime runtime, ManualClock clock, Stepper stepper) {
      GIVEN.add(clock.period().toMillis());
      GIVEN.add(stepper.clock() == clock);
      runtime.spawn(new Object(), ObjectConfig.synchronous(clock));
      stepper.step(3);
      GIVEN.add(clock.instant());
      GIVEN.add(clock);
    }
  }

  @Test
  void aManualTestGetsItsClockAndAStepperOfItClosedAfterIt() {
    Fixtures.run(OnAManualClock.class).assertStatistics(s -> s.succeeded(1));
    assertThat(GIVEN.subList(0, 3)).containsExactly(20L, true, 3L);
    ManualClock clock = (ManualClock) GIVEN.get(3);
    assertThatThrownBy(clock::step)
        .as("closed after the test")
        .isInstanceOf(RuntimeException.class);
  }

  @ActiveTest
  static class AskingForAClockOnTheRealOne {
    @Test
    void clock(ManualClock clock) {}
  }

  @Test
  void aClockOnTheRealClockIsRefusedSayingHowToAskForOne() {
    Events events = Fixtures.run(AskingForAClockOnTheRealOne.class);
    events.assertStatistics(s -> s.failed(1));
    assertThat(Fixtures.failures(events).get(0))
        .hasMessageContaining("ManualClock is given only on a manual clock")
        .hasMessageContaining("@ActiveTest(manualClock = true)");
  }

  @ActiveTest
  static class AnObjectFails {
    @Test
    void fails(ActiveRuntime runtime) {
      Probe probe = Probe.create(runtime);
      ActiveObject<Echo> echo = runtime.spawn(new Echo(probe.ref()));
      echo.send(new Ping(echo.address(), 1)); // a Ping: answered
      echo.send(new Messages.Pong(echo.address(), 2)); // an echo takes no Pong: it fails
    }
  }

  @Test
  void aTestWhoseObjectFailedFailsNamingTheFailure() {
    Events events = Fixtures.run(AnObjectFails.class);
    events.assertStatistics(s -> s.failed(1));
    Throwable failure = Fixtures.failures(events).get(0);
    assertThat(failure)
        .isInstanceOf(AssertionError.class)
        .hasMessageStartingWith("1 object failure(s) in runtime fails-")
        .hasMessageContaining("failed on Pong[")
        .hasMessageContaining("an echo takes a Ping, was Pong[");
    assertThat(failure.getCause()).isInstanceOf(IllegalArgumentException.class);
  }

  @ActiveTest(failOnObjectFailures = false)
  static class AnObjectFailsOnPurpose {
    @Test
    void fails(ActiveRuntime runtime) {
      ActiveObject<Echo> echo = runtime.spawn(new Echo(Probe.create(runtime).ref()));
      echo.send(new Messages.Pong(echo.address(), 2));
    }
  }

  @Test
  void aTestThatProvokesFailuresOnPurposeSaysSo() {
    Fixtures.run(AnObjectFailsOnPurpose.class).assertStatistics(s -> s.succeeded(1));
  }

  @ActiveTest
  static class AGuardThatNeverOpens {
    @Test
    void leaves(ActiveRuntime runtime) {
      runtime.spawn(new Object()).sendWhen(s -> false, s -> {});
    }
  }

  @Test
  void aTestThatLeavesWorkBehindOnTheRealClockFailsSayingSo() {
    Events events = Fixtures.run(AGuardThatNeverOpens.class);
    events.assertStatistics(s -> s.failed(1));
    assertThat(Fixtures.failures(events).get(0))
        .hasMessageContaining("did not shut down cleanly")
        .hasMessageContaining("1 queued event(s)");
  }

  @ActiveTest
  static class InAConstructor {
    InAConstructor(ActiveRuntime runtime) {}

    @Test
    void test() {}
  }

  @Test
  void aConstructorCannotTakeTheTestsRuntime() {
    Events events = Fixtures.run(InAConstructor.class);
    events.assertStatistics(s -> s.failed(1));
    assertThat(Fixtures.failures(events).get(0))
        .hasMessageContaining("ActiveRuntime is given to test methods");
  }
}
