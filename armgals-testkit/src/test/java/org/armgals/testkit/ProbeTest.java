package org.armgals.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ObjectConfig;
import org.armgals.testkit.Messages.Echo;
import org.armgals.testkit.Messages.Ping;
import org.armgals.testkit.Messages.Pong;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

class ProbeTest {

  @Nested
  @ActiveTest(manualClock = true)
  class OnAManualClock {

    @Test
    void aMessageSentAtAnInstantIsTakenAtTheNext(ActiveRuntime runtime, Stepper stepper) {
      Probe probe = Probe.create(runtime, stepper);
      ActiveObject<Echo> echo =
          runtime.spawn(new Echo(probe.ref()), ObjectConfig.synchronous(stepper.clock()));
      echo.send(new Ping(echo.address(), 1));
      // instant 1: the echo takes the ping and answers; instant 2: the probe takes the answer
      assertThat(probe.expectMessage(new Pong(probe.address(), 1), 2))
          .isEqualTo(new Pong(probe.address(), 1));
      assertThat(stepper.instant()).isEqualTo(2);
    }

    @Test
    void aMessageThatComesTooLateFailsNamingTheInstants(ActiveRuntime runtime, Stepper stepper) {
      Probe probe = Probe.create(runtime, stepper);
      ActiveObject<Echo> echo =
          runtime.spawn(new Echo(probe.ref()), ObjectConfig.synchronous(stepper.clock()));
      echo.send(new Ping(echo.address(), 1));
      assertThatThrownBy(() -> probe.expectMessage(1))
          .isInstanceOf(AssertionError.class)
          .hasMessage(
              probe
                  + ": expected a message within 1 instant(s) (instants 1 to 1), received nothing");
      assertThat(probe.expectMessageType(Pong.class, 1).n()).isEqualTo(1);
    }

    @Test
    void anotherMessageThanTheExpectedOneFailsNamingBoth(ActiveRuntime runtime, Stepper stepper) {
      Probe probe = Probe.create(runtime, stepper);
      probe.ref().send(new Ping(probe.address(), 7));
      assertThatThrownBy(() -> probe.expectMessage(new Ping(probe.address(), 8), 3))
          .isInstanceOf(AssertionError.class)
          .hasMessage(
              probe
                  + ": expected "
                  + new Ping(probe.address(), 8)
                  + ", received "
                  + new Ping(probe.address(), 7)
                  + " at instant 1");
    }

    @Test
    void aMessageOfAnotherTypeFailsNamingBothTypes(ActiveRuntime runtime, Stepper stepper) {
      Probe probe = Probe.create(runtime, stepper);
      probe.ref().send(new Ping(probe.address(), 7));
      assertThatThrownBy(() -> probe.expectMessageType(Pong.class, 3))
          .isInstanceOf(AssertionError.class)
          .hasMessageContaining("expected a message of type " + Pong.class.getName())
          .hasMessageContaining("of type " + Ping.class.getName() + " at instant 1");
    }

    @Test
    void expectNoMessageStepsEveryInstantAndFailsOnOne(ActiveRuntime runtime, Stepper stepper) {
      Probe probe = Probe.create(runtime, stepper);
      probe.expectNoMessage(3);
      assertThat(stepper.instant()).isEqualTo(3);
      probe.ref().send(new Ping(probe.address(), 1));
      assertThatThrownBy(() -> probe.expectNoMessage(3))
          .isInstanceOf(AssertionError.class)
          .hasMessage(
              probe
                  + ": expected no message during 3 instant(s), received "
                  + new Ping(probe.address(), 1)
                  + " at instant 4");
    }

    @Test
    void aTimeIsRefusedOnAManualClock(ActiveRuntime runtime, Stepper stepper) {
      Probe probe = Probe.create(runtime, stepper);
      assertThatThrownBy(() -> probe.expectMessage(Duration.ofSeconds(1)))
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("is on a manual clock: expect within a number of instants");
      assertThatThrownBy(() -> probe.expectMessage(0)).hasMessage("instants must be >= 1, was 0");
    }
  }

  @Nested
  @ActiveTest
  class OnTheRealClock {

    @Test
    void aMessageIsExpectedWithinATime(ActiveRuntime runtime) {
      Probe probe = Probe.create(runtime);
      ActiveObject<Echo> echo = runtime.spawn(new Echo(probe.ref()));
      echo.send(new Ping(echo.address(), 3));
      assertThat(probe.expectMessageType(Pong.class, Duration.ofSeconds(10)).n()).isEqualTo(3);
      probe.expectNoMessage(Duration.ofMillis(20));
    }

    @Test
    void noMessageWithinTheTimeFailsSayingSo(ActiveRuntime runtime) {
      Probe probe = Probe.create(runtime);
      assertThatThrownBy(() -> probe.expectMessage(Duration.ofMillis(50)))
          .isInstanceOf(AssertionError.class)
          .hasMessage(probe + ": expected a message within 50 ms, received nothing");
    }

    @Test
    void aMessageWhenNoneWasExpectedFailsNamingIt(ActiveRuntime runtime) {
      Probe probe = Probe.create(runtime);
      probe.ref().send(new Ping(probe.address(), 2));
      assertThatThrownBy(() -> probe.expectNoMessage(Duration.ofSeconds(10)))
          .isInstanceOf(AssertionError.class)
          .hasMessage(
              probe
                  + ": expected no message during 10000 ms, received "
                  + new Ping(probe.address(), 2));
    }

    @Test
    void instantsAreRefusedOnTheRealClock(ActiveRuntime runtime) {
      Probe probe = Probe.create(runtime);
      assertThatThrownBy(() -> probe.expectMessage(3))
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("is on the real clock: expect within a time");
    }
  }
}
