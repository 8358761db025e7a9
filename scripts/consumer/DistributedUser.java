import java.net.ServerSocket;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;
import org.jspecify.annotations.Nullable;

/**
 * What a user of arm-active who distributes does, run by scripts/check-core-classpath.sh on the
 * class path Maven resolves for a project with arm-active, artemis-jakarta-client and
 * artemis-server, as docs/user-guide.md says: an embedded broker, a runtime on it in this JVM and a
 * client over the network that looks a name up and sends an event. Exit status 0 if all holds.
 */
public class DistributedUser {
  record Ping(@Nullable Address sender, Address destination, int n) implements Event {}

  public static void main(String[] args) throws Exception {
    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    Duration wait = Duration.ofSeconds(30);
    CountDownLatch received = new CountDownLatch(10);
    try (EmbeddedBroker broker = EmbeddedBroker.start(port);
        JmsTransport owner =
            JmsTransport.builder().broker(broker.inVmUrl()).allow(Ping.class).build();
        JmsTransport client =
            JmsTransport.builder()
                .broker(broker.nettyUrl().orElseThrow(), broker.user(), broker.password())
                .allow(Ping.class)
                .build();
        ActiveRuntime here = ActiveRuntime.builder().name("owner").transport(owner).build();
        ActiveRuntime there = ActiveRuntime.builder().name("client").transport(client).build()) {
      Address sink = here.spawn((EventProcessor) e -> received.countDown()).address();
      owner.register("sink", sink);
      Address found = client.lookup("sink").getValue(wait);
      for (int i = 0; i < 10; i++) {
        there.ref(found).send(new Ping(null, found, i));
      }
      if (!received.await(wait.toSeconds(), TimeUnit.SECONDS)) {
        throw new AssertionError("the sink got " + (10 - received.getCount()) + " of 10 events");
      }
    }
    System.out.println("DistributedUser: a name looked up and 10 events carried over the broker");
  }
}
