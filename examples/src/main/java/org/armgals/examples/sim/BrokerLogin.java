package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import java.util.Objects;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;
import org.armgals.active.jms.Presence;

/**
 * The login a run uses on a broker and hands to the JVMs it starts (a meta level's, an atom's) in
 * their environment, {@value #USER} and {@value #PASSWORD}, never on their command line. An empty
 * user is no login.
 *
 * @param user the user; empty for none
 * @param password the password; empty with no user
 */
public record BrokerLogin(String user, String password) {
  /** The broker's user, in the environment. */
  public static final String USER = "ARMGALS_BROKER_USER";

  /** The broker's password, in the environment. */
  public static final String PASSWORD = "ARMGALS_BROKER_PASSWORD";

  /** No login. */
  public static final BrokerLogin NONE = new BrokerLogin("", "");

  /** Checks for null. */
  public BrokerLogin {
    requireNonNull(user, "user");
    requireNonNull(password, "password");
  }

  /** The login in this JVM's environment: none without {@value #USER}, no password is empty. */
  public static BrokerLogin fromEnvironment() {
    String user = System.getenv(USER);
    return user == null
        ? NONE
        : new BrokerLogin(user, Objects.requireNonNullElse(System.getenv(PASSWORD), ""));
  }

  /** The login that {@code broker} requires, the one it generated. */
  public static BrokerLogin of(EmbeddedBroker broker) {
    return new BrokerLogin(broker.user(), broker.password());
  }

  /** The environment that hands this login to a child JVM: empty for none. */
  public Map<String, String> environment() {
    return user.isEmpty() ? Map.of() : Map.of(USER, user, PASSWORD, password);
  }

  /** {@code builder} on the broker at {@code url}, with this login if any. */
  public JmsTransport.Builder on(JmsTransport.Builder builder, String url) {
    return user.isEmpty() ? builder.broker(url) : builder.broker(url, user, password);
  }

  /** {@code builder} on the broker at {@code url}, with this login if any. */
  public Presence.Builder on(Presence.Builder builder, String url) {
    return user.isEmpty() ? builder.broker(url) : builder.broker(url, user, password);
  }
}
