package org.armgals.testkit;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.jms.JmsTransport;
import org.armgals.testkit.Messages.Echo;
import org.armgals.testkit.Messages.Ping;
import org.armgals.testkit.Messages.Pong;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.platform.testkit.engine.Events;

/** The broker extension, on fixture classes run as a user's build runs them. */
class EmbeddedBrokerExtensionTest {

  /** What the fixtures were given. */
  static final List<TestBroker> GIVEN = new ArrayList<>();

  @BeforeEach
  void forget() {
    GIVEN.clear();
  }

  @BrokerTest
  static class TwoRuntimes {
    @Test
    void pingPong(TestBroker broker) {
      GIVEN.add(broker);
      JmsTransport eastTransport = broker.transport(b -> b.allow(Ping.class, Pong.class));
      JmsTransport westTransport = broker.transport(b -> b.allow(Ping.class, Pong.class));
      ActiveRuntime east = broker.runtime("east", eastTransport);
      ActiveRuntime west = broker.runtime("west", westTransport);
      Probe probe = Probe.create(east);
      ActiveObject<Echo> echo = west.spawn(new Echo(east.ref(probe.address())));
      echo.send(new Ping(echo.address(), 5));
      probe.expectMessage(new Pong(probe.address(), 5), Duration.ofSeconds(10));
    }

    @Test
    void another(TestBroker broker) {
      GIVEN.add(broker);
    }
  }

  @Test
  void runtimesOnTheBrokerTalkAndTheTestsOfAClassShareItWithTopicsOfTheirOwn() throws Exception {
    Fixtures.run(TwoRuntimes.class).assertStatistics(s -> s.succeeded(2).failed(0));
    assertThat(GIVEN).hasSize(2);
    assertThat(GIVEN.get(0).broker()).isSameAs(GIVEN.get(1).broker());
    assertThat(GIVEN.get(0).prefix()).isNotEqualTo(GIVEN.get(1).prefix());
    URI netty = URI.create(GIVEN.get(0).broker().nettyUrl().orElseThrow());
    assertThat(netty.getHost()).isEqualTo("127.0.0.1");
    assertThat(GIVEN.get(0).broker().password()).hasSizeGreaterThanOrEqualTo(32);
    assertThat(accepts(netty)).as("closed after the class").isFalse();
  }

  @BrokerTest(brokerPerTest = true)
  static class ABrokerEach {
    @Test
    void one(TestBroker broker) throws Exception {
      GIVEN.add(broker);
      assertThat(accepts(URI.create(broker.broker().nettyUrl().orElseThrow()))).isTrue();
    }

    @Test
    void two(TestBroker broker) {
      GIVEN.add(broker);
    }
  }

  @Test
  void aBrokerPerTestIsClosedAfterIt() throws Exception {
    Fixtures.run(ABrokerEach.class).assertStatistics(s -> s.succeeded(2));
    assertThat(GIVEN.get(0).broker()).isNotSameAs(GIVEN.get(1).broker());
    assertThat(GIVEN.get(0).broker().nettyUrl().orElseThrow())
        .isNotEqualTo(GIVEN.get(1).broker().nettyUrl().orElseThrow());
    for (TestBroker b : GIVEN) {
      assertThat(accepts(URI.create(b.broker().nettyUrl().orElseThrow()))).isFalse();
    }
  }

  @BrokerTest
  static class ARemoteObjectFails {
    @Test
    void fails(TestBroker broker) {
      JmsTransport t = broker.transport(b -> b.allow(Ping.class, Pong.class));
      ActiveRuntime west = broker.runtime("west", t);
      ActiveObject<Echo> echo = west.spawn(new Echo(west.spawn(new Object())));
      echo.send(new Pong(echo.address(), 1));
    }
  }

  @Test
  void aTestWhoseRuntimesObjectFailedFailsNamingTheFailure() {
    Events events = Fixtures.run(ARemoteObjectFails.class);
    events.assertStatistics(s -> s.failed(1));
    assertThat(Fixtures.failures(events).get(0))
        .hasMessageStartingWith("1 object failure(s) in runtime west")
        .hasMessageContaining("an echo takes a Ping");
  }

  @BrokerTest
  static class ARemoteObjectFailsOnPurpose {
    @BrokerTest(failOnObjectFailures = false)
    @Test
    void fails(TestBroker broker) {
      ActiveRuntime west = broker.runtime("west", broker.transport());
      ActiveObject<Echo> echo = west.spawn(new Echo(west.spawn(new Object())));
      echo.send(new Pong(echo.address(), 1));
    }
  }

  @Test
  void aTestThatFailsObjectsOnPurposeSaysSoOnItsMethod() {
    Fixtures.run(ARemoteObjectFailsOnPurpose.class).assertStatistics(s -> s.succeeded(1));
  }

  static boolean accepts(URI url) throws IOException {
    try (Socket s = new Socket()) {
      s.connect(new InetSocketAddress(url.getHost(), url.getPort()), 2_000);
      return true;
    } catch (java.net.ConnectException e) {
      return false;
    }
  }
}
