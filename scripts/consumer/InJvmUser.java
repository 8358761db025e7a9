import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.Filter;
import org.armgals.active.ObjectConfig;

/**
 * What a user of arm-active does in one JVM, run by scripts/check-core-classpath.sh on the class
 * path Maven resolves for a project that depends on arm-active alone: Jakarta Messaging must not be
 * there, and an active object must run, filters included. Exit status 0 if all holds.
 */
public class InJvmUser {
  record Ping(Address sender, Address destination, int n) implements Event {}

  /** Keeps what it is sent. */
  static final class Counter implements EventProcessor {
    final List<Integer> seen = new ArrayList<>();

    @Override
    public void process(Event event) {
      seen.add(((Ping) event).n());
    }
  }

  public static void main(String[] args) throws Exception {
    try {
      Class.forName("jakarta.jms.Message");
      throw new AssertionError("jakarta.jms.Message is on the class path of an in-JVM user");
    } catch (ClassNotFoundException expected) {
      // as it should be
    }
    Filter low = Filter.selector("energy < 20 AND kind = 'State'");
    if (!low.matches(Map.of("energy", 12, "kind", "State"))
        || low.matches(Map.of("energy", 25, "kind", "State"))) {
      throw new AssertionError("the filter " + low + " does not mean what it says");
    }
    try (ActiveRuntime runtime = ActiveRuntime.builder().name("in-jvm-user").build()) {
      ActiveObject<Counter> counter = runtime.spawn(new Counter(), ObjectConfig.asynchronous());
      for (int i = 0; i < 100; i++) {
        counter.send(new Ping(counter.address(), counter.address(), i));
      }
      int seen = counter.call(c -> c.seen.size()).getValue(Duration.ofSeconds(10));
      if (seen != 100) {
        throw new AssertionError("the active object saw " + seen + " of 100 events");
      }
    }
    System.out.println("InJvmUser: an active object ran, with no Jakarta Messaging class around");
  }
}
