package org.armgals.active;

import java.util.Optional;

/**
 * An Apache ActiveMQ Artemis broker inside this JVM, the JMS transport's default
 * (docs/architecture.md, runtime semantics 5): persistence off, security off, an in-VM acceptor,
 * and on request a netty acceptor bound to {@code 127.0.0.1} (loopback only, so the absence of
 * credentials reaches no other machine) for runtimes of other JVMs on this host.
 *
 * <p>{@link #close()} stops the broker and leaves none of its non-daemon threads behind.
 * Thread-safe.
 */
public interface EmbeddedBroker extends AutoCloseable {

  /** Starts a broker with only an in-VM acceptor. */
  static EmbeddedBroker start() {
    return EmbeddedArtemis.start(0);
  }

  /**
   * Starts a broker with an in-VM acceptor and a netty acceptor on {@code 127.0.0.1:port}.
   *
   * @throws IllegalArgumentException {@code port} is not in [1, 65535]
   * @throws IllegalStateException the broker did not start (port taken); the cause says why
   */
  static EmbeddedBroker start(int port) {
    if (port < 1 || port > 65_535) {
      throw new IllegalArgumentException("port must be in [1, 65535], was " + port);
    }
    return EmbeddedArtemis.start(port);
  }

  /** The URL of the in-VM acceptor, for clients of this JVM: {@code vm://<n>}. */
  String inVmUrl();

  /** The URL of the netty acceptor, {@code tcp://127.0.0.1:<port>}, if there is one. */
  Optional<String> nettyUrl();

  /** Stops the broker. Idempotent. */
  @Override
  void close();
}
