package org.armgals.active.jms;

import static java.util.Objects.requireNonNull;

import jakarta.jms.JMSException;
import jakarta.jms.Message;
import jakarta.jms.MessageConsumer;
import jakarta.jms.Session;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.armgals.active.ActiveException;
import org.armgals.active.Event;
import org.armgals.active.Filter;
import org.armgals.active.jms.JmsTransport.Topic;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A {@link Subscription}: in memory, its filter is evaluated by {@link Filter#matches}; on the
 * broker, by a consumer whose selector is the filter.
 *
 * <p>A swap opens a consumer with the new selector beside the old one, then publishes a marker that
 * both consumers' selectors take. The old consumer's messages count until its marker, the new one's
 * from its start; events are told apart by (publishing node, sequence number), so that one that
 * reaches both consumers is delivered once: the keys delivered while both consumers run are kept
 * until the next swap, for an event the broker routed to the old queue before the marker and to the
 * new one after it. When both markers are in, the old consumer is closed. All delivery goes through
 * {@link #lock}.
 */
final class JmsSubscription implements Subscription {
  private static final Logger LOG = LoggerFactory.getLogger(JmsSubscription.class);
  private static final long SWAP_NANOS = TimeUnit.SECONDS.toNanos(10);

  private final JmsTransportImpl transport;
  private final Topic topic;
  private final String id;
  private final Consumer<? super Event> handler;
  private final ReentrantLock lock = new ReentrantLock();
  private final Condition swapped = lock.newCondition();

  // guarded by lock
  private volatile Filter filter;
  private Session current;
  private @Nullable Session previous;
  private boolean oldMarker;
  private boolean newMarker;
  private final Set<String> seen = new HashSet<>();
  private boolean closed;

  JmsSubscription(
      JmsTransportImpl transport,
      Topic topic,
      String id,
      Filter filter,
      Consumer<? super Event> handler)
      throws JMSException {
    this.transport = transport;
    this.topic = topic;
    this.id = id;
    this.filter = filter;
    this.handler = handler;
    this.current = open(filter);
  }

  /** The selector of a consumer for {@code f}: others' publications it takes, and our markers. */
  private String selector(Filter f) {
    String published =
        WireProperties.MSG
            + " = 'publish' AND "
            + WireProperties.FROM
            + " <> "
            + WireProperties.literal(transport.node());
    String own = f.expression().isEmpty() ? published : published + " AND (" + f.expression() + ")";
    return "(" + own + ") OR " + WireProperties.MARKER + " = " + WireProperties.literal(id);
  }

  private Session open(Filter f) throws JMSException {
    Session s = transport.connection().createSession(false, Session.AUTO_ACKNOWLEDGE);
    MessageConsumer c = s.createConsumer(s.createTopic(transport.topicName(topic)), selector(f));
    c.setMessageListener(m -> onMessage(s, m));
    return s;
  }

  @Override
  public Filter filter() {
    return filter;
  }

  /** An event published by this transport: delivered in memory if the filter takes it. */
  void local(Event event, Map<String, Object> properties) {
    lock.lock();
    try {
      if (!closed && filter.matches(properties)) {
        handle(event);
      }
    } finally {
      lock.unlock();
    }
  }

  private void onMessage(Session from, Message m) {
    lock.lock();
    try {
      if (closed) {
        return;
      }
      if (from != current && from != previous) {
        return; // a retired consumer's leftovers: published after its marker
      }
      boolean old = from == previous;
      if (m.propertyExists(WireProperties.MARKER)) {
        if (old) {
          oldMarker = true;
        } else if (previous != null) {
          newMarker = true;
        }
        if (oldMarker && newMarker) {
          finishSwap();
        }
        return;
      }
      if (old && oldMarker) {
        return; // published after the swap: the new consumer judges it
      }
      Event e = transport.decodePublished(m);
      if (e == null) {
        return;
      }
      String key =
          m.getStringProperty(WireProperties.FROM) + ":" + m.getObjectProperty(WireProperties.SEQ);
      if (previous != null) {
        if (!seen.add(key)) {
          return; // reached both consumers during the swap
        }
      } else if (!seen.isEmpty() && seen.remove(key)) {
        return; // delivered by the old consumer before its marker, reached the new one after
      }
      handle(e);
    } catch (JMSException | RuntimeException e) {
      transport.rejectPublished(e);
    } finally {
      lock.unlock();
    }
  }

  private void handle(Event e) {
    try {
      handler.accept(e);
    } catch (RuntimeException failure) {
      LOG.error("subscription {} on {}: the handler failed on {}", id, topic, e, failure);
    }
  }

  @Override
  public void swap(Filter next) {
    requireNonNull(next, "next");
    lock.lock();
    try {
      if (closed) {
        throw new IllegalStateException("subscription " + id + " is closed");
      }
      long left = SWAP_NANOS;
      while (previous != null && left > 0) {
        left = swapped.awaitNanos(left); // a swap under way: let it end first
      }
      Session fresh = open(next);
      previous = current;
      current = fresh;
      oldMarker = false;
      newMarker = false;
      seen.clear();
      filter = next;
      transport.publishMarker(topic, id);
      left = SWAP_NANOS;
      while (previous != null && left > 0) {
        left = swapped.awaitNanos(left);
      }
      if (previous != null) {
        throw new IllegalStateException(
            "subscription " + id + ": the broker did not confirm the swap to " + next + " in 10 s");
      }
    } catch (JMSException e) {
      throw new IllegalStateException("subscription " + id + ": cannot swap to " + next, e);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new ActiveException("interrupted while swapping the filter of subscription " + id);
    } finally {
      lock.unlock();
    }
  }

  private void finishSwap() {
    Session old = previous;
    previous = null;
    swapped.signalAll();
    if (old != null) {
      // Closing a session from its own listener would wait for that listener: do it elsewhere.
      Thread.ofVirtual().start(() -> closeQuietly(old));
    }
  }

  @Override
  public void close() {
    lock.lock();
    Session a;
    Session b;
    try {
      if (closed) {
        return;
      }
      closed = true;
      a = current;
      b = previous;
      swapped.signalAll();
    } finally {
      lock.unlock();
    }
    transport.forget(this);
    closeQuietly(a);
    if (b != null) {
      closeQuietly(b);
    }
  }

  Topic topic() {
    return topic;
  }

  private void closeQuietly(Session s) {
    try {
      s.close();
    } catch (JMSException e) {
      LOG.warn("subscription {}: closing a session failed", id, e);
    }
  }

  @Override
  public String toString() {
    return "Subscription[" + id + ", " + topic + ", " + filter + "]";
  }
}
