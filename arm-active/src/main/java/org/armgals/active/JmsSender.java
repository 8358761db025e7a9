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
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.ReentrantLock;
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
 *
 * <p>A request, an answer or a failure is sent on the caller's own thread when nothing is queued or
 * being sent and the session is free ({@link #submit}): a round trip then costs no hand-over to
 * this thread on either side. The session is used by one thread at a time, under {@link #lock};
 * {@link #unsent} counts what was queued and is not sent yet, so a message never overtakes one
 * queued before it.
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
  private final ReentrantLock lock = new ReentrantLock();
  private final AtomicLong unsent = new AtomicLong();

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

  /**
   * Sends {@code o} now, on the calling thread, if it is a request, an answer or a failure, nothing
   * is waiting to be sent and no other thread is using the session; queues it for the sender thread
   * otherwise.
   *
   * @throws InterruptedException if interrupted while the queue is full
   */
  void submit(Outbound o) throws InterruptedException {
    if (isRoundTrip(o) && unsent.get() == 0 && lock.tryLock()) {
      try {
        if (unsent.get() == 0) {
          send(List.of(o));
          return;
        }
      } finally {
        lock.unlock();
      }
    }
    unsent.incrementAndGet();
    try {
      queue.put(o);
    } catch (InterruptedException e) {
      unsent.decrementAndGet();
      throw e;
    }
  }

  /**
   * Requests and their answers (and failures) may go on the caller's thread; everything else keeps
   * the sender thread's order, which a filter swap's markers rely on.
   */
  private static boolean isRoundTrip(Outbound o) {
    if (o == Outbound.STOP || o.batchable()) {
      return false;
    }
    Object kind = o.properties().get(WireProperties.MSG);
    return WireProperties.MSG_REQUEST.equals(kind)
        || WireProperties.MSG_ANSWER.equals(kind)
        || WireProperties.MSG_FAILURE.equals(kind);
  }

  @Override
  public void run() {
    try {
      while (true) {
        drained.add(queue.take());
        queue.drainTo(drained);
        boolean go;
        lock.lock();
        try {
          go = sendDrained();
        } finally {
          lock.unlock();
        }
        unsent.addAndGet(-drained.size());
        drained.clear();
        if (!go) {
          return;
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      lock.lock();
      try {
        session.close();
      } catch (JMSException e) {
        LOG.debug("closing the producing session", e);
      } finally {
        lock.unlock();
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
