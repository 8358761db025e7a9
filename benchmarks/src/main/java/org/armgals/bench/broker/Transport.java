package org.armgals.bench.broker;

import java.util.Locale;

/** How a client reaches the benchmark's broker. */
enum Transport {
  /** Artemis's in-VM connector: same JVM, no sockets. */
  INVM,
  /** Netty over TCP on 127.0.0.1. */
  NETTY;

  String label() {
    return name().toLowerCase(Locale.ROOT);
  }
}
