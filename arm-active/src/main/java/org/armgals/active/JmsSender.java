package org.armgals.active;

import jakarta.jms.BytesMessage;
import jakarta.jms.JMSException;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Function;
import org.armgals.active.JmsTransport.Topic;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The body of a transport's sender thread, the only user of its producing session: takes what is
 * queued, as much as is there, and sends it. Events of one route (topic and destination runtime)
 * that were queued together travel in one message, up to {@code maxBatch}; a message that is not
 * batchable (a request) first sends the events queued before it on its route, so every route keeps
 * its queue order. Routes do not wait for each other.
 */
final class JmsSender implements Runnable {
  private static final Logger LOG = LoggerFactory.getLogger(JmsSender.class);

  private final BlockingQueue<Outbound> queue;
  private final Session session;
  private final MessageProducer producer;
  private final int maxBatch;
  private final int maxBytes;
  private final LongAdder sent;
  private final LongAdder batches;
  private final String node;
  private final Map<Topic, jakarta.jms.Topic> destinations = new EnumMap<>(Topic.class);
  private final List<Outbound> drained = new ArrayList<>();
  private final Map<String, List<Outbound>> pending = new LinkedHashMap<>();

  JmsSender(
      BlockingQueue<Outbound> queue,
      Session session,
      MessageProducer producer,
      Function<Topic, String> topicNames,
      int maxBatch,
      int maxBytes,
      LongAdder sent,
      LongAdder batches,
      String node)
      throws JMSException {
    this.queue = queue;
    this.session = session;
    this.producer = producer;
    this.maxBatch = maxBatch;
    this.maxBytes = maxBytes;
    this.sent = sent;
    this.batches = batches;
    this.node = node;
    for (Topic t : Topic.values()) {
      destinations.put(t, session.createTopic(topicNames.apply(t)));
    }
  }

  @Override
  public void run() {
    try {
      while (true) {
        drained.add(queue.take());
        queue.drainTo(drained);
        boolean go = sendDrained();
        drained.clear();
        if (!go) {
          return;
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      try {
        session.close();
      } catch (JMSException e) {
        LOG.debug("closing the producing session", e);
      }
    }
  }

  /** Sends {@link #drained}; false at {@link Outbound#STOP}. */
  private boolean sendDrained() {
    boolean go = true;
    for (Outbound o : drained) {
      if (o == Outbound.STOP) {
        go = false;
        break;
      }
      String route = o.route();
      if (o.batchable() && route != null) {
        List<Outbound> events = pending.computeIfAbsent(route, k -> new ArrayList<>());
        events.add(o);
        if (events.size() == maxBatch) {
          flush(route);
        }
      } else {
        if (route != null) {
          flush(route);
        }
        send(List.of(o));
      }
    }
    for (String route : List.copyOf(pending.keySet())) {
      flush(route);
    }
    return go;
  }

  private void flush(String route) {
    List<Outbound> events = pending.remove(route);
    if (events != null && !events.isEmpty()) {
      send(events);
    }
  }

  private void send(List<Outbound> group) {
    Outbound first = group.get(0);
    int bytes = 5;
    for (Outbound o : group) {
      bytes += o.value().length;
    }
    if (group.size() > 1 && bytes > maxBytes) {
      int half = group.size() / 2;
      send(group.subList(0, half));
      send(group.subList(half, group.size()));
      return;
    }
    try {
      BytesMessage m = session.createBytesMessage();
      List<byte[]> values = new ArrayList<>(group.size());
      for (Outbound o : group) {
        values.add(o.value());
      }
      m.writeBytes(WireCodec.body(values));
      if (group.size() == 1) {
        for (Map.Entry<String, Object> p : first.properties().entrySet()) {
          m.setObjectProperty(p.getKey(), p.getValue());
        }
      } else {
        m.setStringProperty(WireProperties.MSG, WireProperties.MSG_BATCH);
        m.setObjectProperty(WireProperties.TO, first.properties().get(WireProperties.TO));
        m.setIntProperty(WireProperties.COUNT, group.size());
        batches.increment();
      }
      // Counted before the send: the answer to a request may come back before send returns.
      int counted = counted(first) ? group.size() : 0;
      sent.add(counted);
      try {
        producer.send(destinations.get(first.topic()), m);
      } catch (JMSException | RuntimeException e) {
        sent.add(-counted);
        throw e;
      }
    } catch (JMSException | RuntimeException e) {
      LOG.error(
          "JMS transport {}: {} message(s) on {} lost: {}",
          node,
          group.size(),
          first.topic(),
          e.toString());
    }
  }

  /** Whether a message counts as sent: events, requests and answers; not markers or look-ups. */
  private static boolean counted(Outbound o) {
    Object kind = o.properties().get(WireProperties.MSG);
    return kind != null && !WireProperties.MSG_LOOKUP.equals(kind);
  }
}
