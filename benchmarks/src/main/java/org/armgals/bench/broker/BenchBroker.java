package org.armgals.bench.broker;

import jakarta.jms.ConnectionFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.jms.EmbeddedBroker;

/**
 * The brokers every implementation of the benchmark runs over: the runtime's own {@link
 * EmbeddedBroker}, twice, each with an in-VM acceptor and a netty acceptor bound to 127.0.0.1 that
 * requires its login: one without a journal, for at-most-once runs, and one with a journal in a
 * temporary directory (persistent messages are synced to disk before the broker confirms them), for
 * at-least-once runs. The raw baseline and armgals meet the very same broker.
 */
final class BenchBroker implements AutoCloseable {
  private final EmbeddedBroker plain;
  private final EmbeddedBroker journaled;
  private final Path journal;

  private BenchBroker(EmbeddedBroker plain, EmbeddedBroker journaled, Path journal) {
    this.plain = plain;
    this.journaled = journaled;
    this.journal = journal;
  }

  static BenchBroker start(int plainPort, int journaledPort) throws IOException {
    Path journal = Files.createTempDirectory("armgals-bench-journal-");
    EmbeddedBroker plain = EmbeddedBroker.start(plainPort);
    try {
      return new BenchBroker(
          plain, EmbeddedBroker.builder().port(journaledPort).journal(journal).start(), journal);
    } catch (RuntimeException e) {
      plain.close();
      throw e;
    }
  }

  private EmbeddedBroker broker(Guarantee guarantee) {
    return guarantee == Guarantee.ALO ? journaled : plain;
  }

  /** The URL a client of {@code transport} connects to. */
  String url(Transport transport, Guarantee guarantee) {
    EmbeddedBroker b = broker(guarantee);
    return switch (transport) {
      case INVM -> b.inVmUrl();
      case NETTY ->
          b.nettyUrl()
              .orElseThrow(() -> new IllegalStateException("the broker has no netty acceptor"));
    };
  }

  /** The broker's user (needed over netty only). */
  String user(Guarantee guarantee) {
    return broker(guarantee).user();
  }

  /** The password of {@link #user}. */
  String password(Guarantee guarantee) {
    return broker(guarantee).password();
  }

  ConnectionFactory connectionFactory(Transport transport, Guarantee guarantee) {
    return new ActiveMQConnectionFactory(
        url(transport, guarantee), user(guarantee), password(guarantee));
  }

  @Override
  public void close() throws IOException {
    plain.close();
    journaled.close();
    try (Stream<Path> files = Files.walk(journal)) {
      files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
    }
  }
}
