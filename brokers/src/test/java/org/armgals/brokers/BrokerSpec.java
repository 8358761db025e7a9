package org.armgals.brokers;

import static java.util.Objects.requireNonNull;

import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;

/**
 * What a standalone broker instance is created with: its name, the port of its one acceptor on
 * 127.0.0.1, the user a client logs in as, for a cluster member the cluster's credentials and the
 * acceptors of the other members (static connectors), and whether it keeps a journal (persistent
 * messages, durable subscriptions and the duplicate-id cache outlive a kill).
 */
record BrokerSpec(
    String name, int port, Credentials user, Optional<ClusterSpec> cluster, boolean persistent) {

  /** A user name and its password. */
  record Credentials(String user, String password) {
    Credentials {
      requireNonNull(user, "user");
      requireNonNull(password, "password");
      if (user.isBlank() || password.isBlank()) {
        throw new IllegalArgumentException(
            "user and password must not be blank, were '"
                + user
                + "' and a password of "
                + password.length()
                + " characters");
      }
    }

    /** A user of that name with a fresh random password. */
    static Credentials random(String user) {
      byte[] bytes = new byte[16];
      new SecureRandom().nextBytes(bytes);
      return new Credentials(user, HexFormat.of().formatHex(bytes));
    }
  }

  /** Membership of a symmetric cluster with static connectors and on-demand load balancing. */
  record ClusterSpec(Credentials clusterUser, List<Integer> peerPorts) {
    ClusterSpec {
      requireNonNull(clusterUser, "clusterUser");
      peerPorts = List.copyOf(peerPorts);
      if (peerPorts.isEmpty()) {
        throw new IllegalArgumentException("a cluster member needs at least one peer, had none");
      }
    }
  }

  BrokerSpec {
    requireNonNull(name, "name");
    requireNonNull(user, "user");
    requireNonNull(cluster, "cluster");
    if (!name.matches("[a-z][a-z0-9-]*")) {
      throw new IllegalArgumentException(
          "name must be lower-case letters, digits and '-', starting with a letter, was '"
              + name
              + "'");
    }
    if (port < 1 || port > 65535) {
      throw new IllegalArgumentException("port must be in [1, 65535], was " + port);
    }
  }

  /** The URL a Jakarta JMS client connects to. */
  String url() {
    return "tcp://127.0.0.1:" + port;
  }
}
