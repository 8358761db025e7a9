package org.armgals.active.jms;

import static java.util.Objects.requireNonNull;

import jakarta.jms.Connection;
import jakarta.jms.DeliveryMode;
import jakarta.jms.JMSException;
import jakarta.jms.Message;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import jakarta.jms.Topic;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.apache.activemq.artemis.api.core.client.FailoverEventType;
import org.apache.activemq.artemis.jms.client.ActiveMQConnection;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.PresenceEvent;
import org.armgals.active.spi.PresenceEvent.Joined;
import org.armgals.active.spi.PresenceEvent.Left;
import org.armgals.active.spi.PresenceEvent.Lost;
import org.armgals.active.spi.PresenceListener;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A presence over one JMS connection: a producer session used by the beating thread only (or by the
 * caller of {@link #doWork} when stepped by hand, and by {@link #close} once that thread has
 * stopped), and a consumer session whose listener thread records the beats heard. The map of last
 * beats, the connection state and every listener call are guarded by this object's monitor.
 */
final class PresenceImpl implements Presence {
  static final String TOPIC = "arm/Presence";
  static final String RUNTIME = "armgals_runtime";
  static final String KIND = "armgals_presence";
  static final String BEAT = "beat";
  static final String LEAVE = "leave";

  private static final Logger LOG = LoggerFactory.getLogger(PresenceImpl.class);
  private static final Duration CLOSE_WAIT = Duration.ofSeconds(10);

  private final String runtime;
  private final TimeSource time;
  private final long periodNanos;
  private final long lostAfterNanos;
  private final List<PresenceListener> listeners;
  private final Connection connection;
  private final Session out;
  private final MessageProducer producer;
  private final @Nullable ScheduledExecutorService runner;
  private final Map<String, Long> lastBeat = new HashMap<>();
  private final AtomicLong listenerFailures = new AtomicLong();
  private boolean connected = true;
  private boolean closed;

  private PresenceImpl(
      Presence.Builder b,
      Connection connection,
      Session out,
      MessageProducer producer,
      boolean scheduled) {
    this.runtime = requireNonNull(b.runtime, "runtime");
    this.time = b.timeSource;
    this.periodNanos = b.period.toNanos();
    this.lostAfterNanos = b.period.toNanos() * b.missedBeats;
    this.listeners = List.copyOf(b.listeners);
    this.connection = connection;
    this.out = out;
    this.producer = producer;
    this.runner =
        scheduled
            ? Executors.newSingleThreadScheduledExecutor(
                Thread.ofPlatform().daemon().name("presence " + runtime).factory())
            : null;
  }

  /**
   * Connects and subscribes; if {@code scheduled}, beats and sweeps every period on a thread of its
   * own, otherwise only when {@link #doWork} is called (tests step it by hand).
   */
  static PresenceImpl start(Presence.Builder b, boolean scheduled) {
    String url = requireNonNull(b.url, "url");
    if (!url.contains("reconnectAttempts=")) {
      url += (url.contains("?") ? "&" : "?") + "reconnectAttempts=-1";
    }
    ActiveMQConnectionFactory factory = new ActiveMQConnectionFactory(url, b.user, b.password);
    Connection connection = null;
    try {
      connection = factory.createConnection();
      Session out = connection.createSession(false, Session.AUTO_ACKNOWLEDGE);
      Topic topic = out.createTopic(b.prefix + "/" + TOPIC);
      MessageProducer producer = out.createProducer(topic);
      producer.setDeliveryMode(DeliveryMode.NON_PERSISTENT);
      // A beat older than the allowance says nothing any more: let the broker drop it.
      producer.setTimeToLive(Math.max(1, b.period.toMillis() * b.missedBeats));
      PresenceImpl presence = new PresenceImpl(b, connection, out, producer, scheduled);
      ((ActiveMQConnection) connection).setFailoverListener(presence::onFailover);
      Session in = connection.createSession(false, Session.AUTO_ACKNOWLEDGE);
      in.createConsumer(topic).setMessageListener(presence::onMessage);
      connection.start();
      presence.beat(BEAT);
      if (presence.runner != null) {
        presence.runner.scheduleAtFixedRate(
            presence::doWorkLogged,
            presence.periodNanos,
            presence.periodNanos,
            TimeUnit.NANOSECONDS);
      }
      return presence;
    } catch (JMSException | RuntimeException e) {
      if (connection != null) {
        try {
          connection.close();
        } catch (JMSException closing) {
          e.addSuppressed(closing);
        }
      }
      throw new IllegalStateException("presence " + b.runtime + " cannot use broker " + url, e);
    }
  }

  /** One step: beat, then declare lost every runtime silent for longer than the allowance. */
  void doWork() throws JMSException {
    beat(BEAT);
    sweep();
  }

  private void doWorkLogged() {
    try {
      doWork();
    } catch (JMSException | RuntimeException e) {
      LOG.warn("presence {}: a beat or sweep failed; trying again next period", runtime, e);
    }
  }

  private void beat(String kind) throws JMSException {
    Message beat = out.createMessage();
    beat.setStringProperty(RUNTIME, runtime);
    beat.setStringProperty(KIND, kind);
    producer.send(beat);
  }

  private synchronized void sweep() {
    if (!connected || closed) {
      return;
    }
    long now = time.nanoTime();
    List<String> silent = new ArrayList<>();
    lastBeat.forEach(
        (peer, at) -> {
          if (now - at > lostAfterNanos) {
            silent.add(peer);
          }
        });
    for (String peer : silent) {
      long at = lastBeat.remove(peer);
      tell(new Lost(peer, Duration.ofNanos(now - at)));
    }
  }

  private synchronized void onMessage(Message message) {
    String peer;
    String kind;
    try {
      peer = message.getStringProperty(RUNTIME);
      kind = message.getStringProperty(KIND);
    } catch (JMSException e) {
      LOG.warn("presence {}: unreadable presence message dropped", runtime, e);
      return;
    }
    if (peer == null || kind == null) {
      LOG.warn("presence {}: a presence message lacks {} or {}; dropped", runtime, RUNTIME, KIND);
      return;
    }
    if (peer.equals(runtime) || closed) {
      return;
    }
    switch (kind) {
      case BEAT -> {
        if (lastBeat.put(peer, time.nanoTime()) == null) {
          tell(new Joined(peer));
        }
      }
      case LEAVE -> {
        if (lastBeat.remove(peer) != null) {
          tell(new Left(peer));
        }
      }
      default -> LOG.warn("presence {}: unknown presence kind '{}' from {}", runtime, kind, peer);
    }
  }

  private synchronized void onFailover(FailoverEventType event) {
    switch (event) {
      case FAILURE_DETECTED -> connected = false;
      case FAILOVER_COMPLETED -> {
        connected = true;
        long now = time.nanoTime();
        lastBeat.replaceAll((peer, at) -> now);
      }
      case FAILOVER_FAILED -> LOG.warn("presence {}: reconnection to the broker failed", runtime);
    }
  }

  /** Tells every listener; called with the monitor held, so one event at a time, in order. */
  private void tell(PresenceEvent event) {
    for (PresenceListener listener : listeners) {
      try {
        listener.onPresence(event);
      } catch (RuntimeException e) {
        listenerFailures.incrementAndGet();
        LOG.error("presence {}: listener {} failed on {}", runtime, listener, event, e);
      }
    }
  }

  @Override
  public String runtime() {
    return runtime;
  }

  @Override
  public synchronized Set<String> peers() {
    return Set.copyOf(lastBeat.keySet());
  }

  @Override
  public long listenerFailures() {
    return listenerFailures.get();
  }

  @Override
  public void close() {
    synchronized (this) {
      if (closed) {
        return;
      }
      closed = true;
    }
    try {
      if (runner != null) {
        runner.shutdownNow();
        if (!runner.awaitTermination(CLOSE_WAIT.toNanos(), TimeUnit.NANOSECONDS)) {
          LOG.warn("presence {}: its beating thread did not stop within {}", runtime, CLOSE_WAIT);
        }
      }
      beat(LEAVE);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } catch (JMSException e) {
      LOG.warn("presence {}: could not say it leaves; others will find it lost", runtime, e);
    } finally {
      try {
        connection.close();
      } catch (JMSException e) {
        LOG.warn("presence {}: closing the connection failed", runtime, e);
      }
    }
  }

  @Override
  public String toString() {
    return "presence " + runtime;
  }
}
