package org.armgals.active.jms;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.apache.activemq.artemis.core.config.impl.ConfigurationImpl;
import org.apache.activemq.artemis.core.remoting.impl.invm.InVMConnector;
import org.apache.activemq.artemis.core.server.ActiveMQServer;
import org.apache.activemq.artemis.core.server.embedded.EmbeddedActiveMQ;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** {@link EmbeddedBroker} on {@link EmbeddedActiveMQ}. */
final class EmbeddedArtemis implements EmbeddedBroker {
  private static final Logger LOG = LoggerFactory.getLogger(EmbeddedArtemis.class);
  private static final AtomicInteger IDS = new AtomicInteger(ProcessHandle.current().hashCode());

  /** Embedded brokers started and not yet stopped in this JVM. */
  private static final AtomicInteger LIVE = new AtomicInteger();

  private final EmbeddedActiveMQ server;
  private final String inVmUrl;
  private final @Nullable String nettyUrl;
  private final String user;
  private final String password;
  private final @Nullable Path dir;
  private final AtomicBoolean closed = new AtomicBoolean();

  private EmbeddedArtemis(
      EmbeddedActiveMQ server,
      String inVmUrl,
      @Nullable String nettyUrl,
      String user,
      String password,
      @Nullable Path dir) {
    this.server = server;
    this.inVmUrl = inVmUrl;
    this.nettyUrl = nettyUrl;
    this.user = user;
    this.password = password;
    this.dir = dir;
  }

  /** A login for one run: a fixed user and 32 random hex digits. */
  private static String generatedPassword() {
    byte[] bytes = new byte[16];
    new SecureRandom().nextBytes(bytes);
    return HexFormat.of().formatHex(bytes);
  }

  /** A started broker. */
  static EmbeddedArtemis start(EmbeddedBroker.Builder b) {
    int id = IDS.incrementAndGet() & 0x7fff_ffff;
    String inVm = "vm://" + id;
    int port = b.port;
    Path keyStore = b.keyStore;
    String netty = port > 0 ? "tcp://127.0.0.1:" + port : null;
    String user = b.user != null ? b.user : "armgals";
    String password = b.password != null ? b.password : generatedPassword();
    Path journal = b.journal;
    Path dir;
    try {
      // Without a journal, paging of a full address still needs a directory.
      dir =
          journal != null
              ? Files.createDirectories(journal)
              : Files.createTempDirectory("armgals-broker-");
    } catch (IOException e) {
      throw new IllegalStateException("cannot make the embedded broker's directory", e);
    }
    EmbeddedActiveMQ server = new EmbeddedActiveMQ();
    try {
      ConfigurationImpl c = new ConfigurationImpl();
      c.setName("armgals-" + id);
      c.setPersistenceEnabled(journal != null);
      // An in-VM-only broker is reachable by this JVM's code alone: security would check nothing.
      c.setSecurityEnabled(netty != null);
      if (netty != null) {
        // Every connection authenticates anew: an in-VM login must never stand for a network one.
        c.setAuthenticationCacheSize(0);
        c.setAuthorizationCacheSize(0);
        server.setSecurityManager(new BrokerLogin(user, password));
      }
      c.setJMXManagementEnabled(false);
      c.setGracefulShutdownEnabled(false);
      c.setBrokerInstance(dir.toFile());
      c.setPagingDirectory(dir.resolve("paging").toString());
      c.setBindingsDirectory(dir.resolve("bindings").toString());
      c.setJournalDirectory(dir.resolve("journal").toString());
      c.setLargeMessagesDirectory(dir.resolve("large").toString());
      c.addAcceptorConfiguration("in-vm", inVm);
      if (netty != null) {
        c.addAcceptorConfiguration(
            "netty",
            keyStore == null
                ? netty
                : netty
                    + "?sslEnabled=true;keyStorePath="
                    + keyStore.toAbsolutePath()
                    + ";keyStorePassword="
                    + b.keyStorePassword);
      }
      server.setConfiguration(c);
      server.start();
      if (!server.getActiveMQServer().isActive()) {
        throw new IllegalStateException("the broker did not become active");
      }
    } catch (Exception e) {
      stopQuietly(server);
      if (journal == null) {
        delete(dir);
      }
      throw new IllegalStateException(
          "embedded Artemis broker did not start ("
              + inVm
              + (netty != null ? ", " + netty : "")
              + ")",
          e);
    }
    LIVE.incrementAndGet();
    LOG.info(
        "embedded Artemis broker started on {}{}{}",
        inVm,
        netty != null
            ? " and " + netty + (keyStore != null ? " (TLS)" : "") + ", login required"
            : "",
        journal != null ? ", journal in " + journal : "");
    return new EmbeddedArtemis(
        server,
        inVm,
        netty == null ? null : keyStore == null ? netty : netty + "?sslEnabled=true",
        user,
        password,
        journal == null ? dir : null);
  }

  /** The broker itself, for tests that watch what reaches it. */
  ActiveMQServer server() {
    return server.getActiveMQServer();
  }

  @Override
  public String inVmUrl() {
    return inVmUrl;
  }

  @Override
  public Optional<String> nettyUrl() {
    return Optional.ofNullable(nettyUrl);
  }

  @Override
  public String user() {
    return user;
  }

  @Override
  public String password() {
    return password;
  }

  @Override
  public void close() {
    if (closed.compareAndSet(false, true)) {
      stopQuietly(server);
      Path temporary = dir;
      if (temporary != null) {
        delete(temporary);
      }
      if (LIVE.decrementAndGet() == 0) {
        // In-VM connections share one static pool of non-daemon threads; with no embedded broker
        // left there is no in-VM connection either, and the pool would keep the JVM alive.
        InVMConnector.resetThreadPool();
      }
      LOG.info("embedded Artemis broker {} stopped", inVmUrl);
    }
  }

  private static void stopQuietly(EmbeddedActiveMQ server) {
    try {
      server.stop();
    } catch (Exception e) {
      LOG.warn("embedded Artemis broker did not stop cleanly", e);
    }
  }

  private static void delete(Path dir) {
    try (Stream<Path> files = Files.walk(dir)) {
      files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
    } catch (IOException e) {
      LOG.warn("could not delete {}", dir, e);
    }
  }

  @Override
  public String toString() {
    return "EmbeddedBroker[" + inVmUrl + (nettyUrl != null ? ", " + nettyUrl : "") + "]";
  }
}
