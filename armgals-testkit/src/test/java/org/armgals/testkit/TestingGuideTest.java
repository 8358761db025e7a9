package org.armgals.testkit;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ObjectConfig;
import org.armgals.active.jms.JmsTransport;
import org.armgals.testkit.Messages.Echo;
import org.armgals.testkit.Messages.Ping;
import org.armgals.testkit.Messages.Pong;
import org.junit.jupiter.api.Test;

/**
 * The code of docs/testing.md: each region below is a block of that page (DocSnippetsTest), and the
 * tests shown there pass.
 */
class TestingGuideTest {

  // tag::real-time[]
  @ActiveTest
  static class EchoTest {
    @Test
    void answersEachPing(ActiveRuntime runtime) {
      Probe probe = Probe.create(runtime);
      ActiveObject<Echo> echo = runtime.spawn(new Echo(probe.ref()));

      echo.send(new Ping(echo.address(), 1));

      probe.expectMessage(new Pong(probe.address(), 1), Duration.ofSeconds(5));
      probe.expectNoMessage(Duration.ofMillis(50));
    }
  }

  // end::real-time[]

  // tag::manual[]
  @ActiveTest(manualClock = true, periodMillis = 10)
  static class ReactiveEchoTest {
    @Test
    void answersAtTheNextInstant(ActiveRuntime runtime, Stepper stepper) {
      Probe probe = Probe.create(runtime, stepper); // a synchronous probe on the test's clock
      ActiveObject<Echo> echo =
          runtime.spawn(new Echo(probe.ref()), ObjectConfig.synchronous(stepper.clock()));

      echo.send(new Ping(echo.address(), 1));

      // instant 1: the echo takes the ping and answers; instant 2: the probe takes the answer
      probe.expectMessage(new Pong(probe.address(), 1), 2);
      probe.expectNoMessage(5);
      assertThat(stepper.instant()).isEqualTo(7);
    }
  }

  // end::manual[]

  // tag::broker[]
  @BrokerTest
  static class TwoRuntimesTest {
    @Test
    void aPingCrossesTheBroker(TestBroker broker) {
      JmsTransport eastTransport = broker.transport(b -> b.allow(Ping.class, Pong.class));
      JmsTransport westTransport = broker.transport(b -> b.allow(Ping.class, Pong.class));
      ActiveRuntime east = broker.runtime("east", eastTransport);
      ActiveRuntime west = broker.runtime("west", westTransport);

      Probe probe = Probe.create(east);
      ActiveObject<Echo> echo = west.spawn(new Echo(west.ref(probe.address())));
      echo.send(new Ping(echo.address(), 1));

      probe.expectMessage(new Pong(probe.address(), 1), Duration.ofSeconds(10));
    }
  }

  // end::broker[]

  @Test
  void theGuidesTestsPass() {
    Fixtures.run(EchoTest.class).assertStatistics(s -> s.succeeded(1).failed(0));
    Fixtures.run(ReactiveEchoTest.class).assertStatistics(s -> s.succeeded(1).failed(0));
    Fixtures.run(TwoRuntimesTest.class).assertStatistics(s -> s.succeeded(1).failed(0));
  }
}
