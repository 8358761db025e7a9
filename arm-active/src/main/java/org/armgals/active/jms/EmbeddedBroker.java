package org.armgals.active.jms;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import java.util.Optional;
import org.jspecify.annotations.Nullable;

/**
 * An Apache ActiveMQ Artemis broker inside this JVM, the JMS transport's default
 * (docs/architecture.md, runtime semantics 5): an in-VM acceptor for clients of this JVM, and on
 * request a netty acceptor bound to {@code 127.0.0.1} for runtimes of other JVMs on this host.
 *
 * <p>Closed by default: a client of the netty acceptor must log in, with the login given to {@link
 * Builder#login} or, without one, a login generated for this run ({@link #user()}, {@link
 * #password()}), which a launcher hands to the JVMs it starts (in their environment, not on their
 * command line). A client without it, or with a wrong one, is refused before it can send, receive
 * or look a name up. Clients of the in-VM acceptor are this JVM's own code and need no login. The
 * netty acceptor may take TLS only ({@link Builder#tls}). Persistence is off unless a journal
 * directory is given ({@link Builder#journal}), which at-least-once delivery across a restart of
 * the broker needs.
 *
 * <p>{@link #close()} stops the broker and leaves none of its non-daemon threads behind.
 * Thread-safe.
 */
public interface EmbeddedBroker extends AutoCloseable {

  /** Starts a broker with only an in-VM acceptor. */
  static EmbeddedBroker start() {
    return builder().start();
  }

  /**
   * Starts a broker with an in-VM acceptor and a netty acceptor on {@code 127.0.0.1:port} that
   * requires a login generated for this run.
   *
   * @throws IllegalArgumentException {@code port} is not in [1, 65535]
   * @throws IllegalStateException the broker did not start (port taken); the cause says why
   */
  static EmbeddedBroker start(int port) {
    return builder().port(port).start();
  }

  /** A builder: in-VM only, no journal, until told otherwise. */
  static Builder builder() {
    return new Builder();
  }

  /** The URL of the in-VM acceptor, for clients of this JVM: {@code vm://<n>}. */
  String inVmUrl();

  /**
   * The URL of the netty acceptor, {@code tcp://127.0.0.1:<port>}, with {@code sslEnabled=true} if
   * it takes TLS only, if there is one.
   */
  Optional<String> nettyUrl();

  /** The user a client of the netty acceptor logs in as. */
  String user();

  /** The password of {@link #user()}: the configured one, or the one generated for this run. */
  String password();

  /** Stops the broker. Idempotent. */
  @Override
  void close();

  /** Settings of an embedded broker; validated by {@link #start()}. Not thread-safe. */
  final class Builder {
    int port;
    @Nullable String user;
    @Nullable String password;
    @Nullable Path keyStore;
    @Nullable String keyStorePassword;
    @Nullable Path journal;

    Builder() {}

    /** Adds a netty acceptor on {@code 127.0.0.1:port}; it requires the login. */
    public Builder port(int port) {
      if (port < 1 || port > 65_535) {
        throw new IllegalArgumentException("port must be in [1, 65535], was " + port);
      }
      this.port = port;
      return this;
    }

    /** The login the netty acceptor requires; default one generated for this run. */
    public Builder login(String user, String password) {
      requireNonNull(user, "user");
      requireNonNull(password, "password");
      if (user.isBlank() || password.length() < 8) {
        throw new IllegalArgumentException(
            "the login needs a user and a password of at least 8 characters, was user '"
                + user
                + "' and a password of "
                + password.length());
      }
      this.user = user;
      this.password = password;
      return this;
    }

    /**
     * The netty acceptor takes TLS only, with the key and certificate of the PKCS#12 (or JKS) key
     * store {@code keyStore}; clients trust it with {@code sslEnabled=true&trustStorePath=...}.
     */
    public Builder tls(Path keyStore, String keyStorePassword) {
      this.keyStore = requireNonNull(keyStore, "keyStore");
      this.keyStorePassword = requireNonNull(keyStorePassword, "keyStorePassword");
      return this;
    }

    /**
     * Turns persistence on, with the journal, bindings and duplicate-id cache in {@code directory}
     * (created if missing, kept after {@link EmbeddedBroker#close()}): persistent messages and
     * durable subscriptions outlive the broker, as at-least-once delivery across a restart needs.
     */
    public Builder journal(Path directory) {
      this.journal = requireNonNull(directory, "directory");
      return this;
    }

    /**
     * A started broker.
     *
     * @throws IllegalArgumentException TLS or a login without a netty acceptor
     * @throws IllegalStateException the broker did not start (port taken, unreadable key store);
     *     the cause says why
     */
    public EmbeddedBroker start() {
      if (port == 0 && (keyStore != null || user != null)) {
        throw new IllegalArgumentException(
            "a login or TLS is for the netty acceptor; give it a port with port(...)");
      }
      return EmbeddedArtemis.start(this);
    }
  }
}
