package org.armgals.active.jms;

import jakarta.jms.BytesMessage;
import jakarta.jms.DeliveryMode;
import jakarta.jms.JMSException;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import java.time.Duration;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Function;
import org.apache.activemq.artemis.api.core.Message;
import org.armgals.active.BufferFullException;
import org.armgals.active.OverflowPolicy;
import org.armgals.active.jms.JmsTransport.Topic;
import org.armgals.active.spi.IdleStrategy;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The body of one of a transport's sender threads, the only user of its producing session: takes
 * what is queued, as much as is there, and sends it. Events of one route (topic, destination
 * runtime and guarantee) that were queued together travel in one message, up to {@code maxBatch}; a
 * message that is not batchable (a request) first sends the events queued before it on its route,
 * so every route keeps its queue order. Routes do not wait for each other. Every message of a route
 * carries the route's sequence numbers ({@link WireProperties#FROM}, {@link WireProperties#RSEQ}):
 * the receiver counts a gap as lost ({@link RouteLedger}).
 *
 * <p>At-most-once messages are non-persistent and sent once (a send the broker refuses shows as a
 * gap at the receiver); at-least-once messages are persistent, carry Artemis's duplicate-detection
 * id ({@code _AMQ_DUPL_ID}, the route and its sequence number) and are sent again, with the same
 * id, until the broker has confirmed them (a blocking durable send) or the transport closes. Both
 * kinds share a route when they go to the same runtime on the same topic, and keep its order: a
 * batch holds events of one kind only.
 *
 * <p>The queue is bounded and applies an {@link OverflowPolicy} when full, on the caller's thread:
 * a blocking policy waits for room while the connection is up (a broker that is there makes room)
 * and refuses at once while it is down, so that no caller waits for a broker that is away;
 * at-least-once messages are never dropped (a drop policy refuses them with {@link
 * BufferFullException}).
 *
 * <p>An at-most-once request, answer or failure is sent on the caller's own thread when the
 * connection is up, nothing is queued or being sent and the session is free ({@link #submit}): a
 * round trip then costs no hand-over to this thread on either side. The session is used by one
 * thread at a time, under {@link #lock}; {@link #queued} counts what was queued and is not sent
 * yet, so a message never overtakes one queued before it.
 */
final class JmsSender implements Runnable {
  private static final Logger LOG = LoggerFactory.getLogger(JmsSender.class);

  /** How long a blocked sender waits for room before it looks at the connection again. */
  private static final long BLOCK_SLICE_NANOS = TimeUnit.MILLISECONDS.toNanos(1);

  /** How long the at-least-once sender waits before it sends a refused message again. */
  private static final Duration RETRY = Duration.ofMillis(100);

  /** The settings and counters a sender shares with its transport. */
  record Context(
      String node,
      int capacity,
      OverflowPolicy policy,
      int maxBatch,
      int maxBytes,
      LongAdder sent,
      LongAdder batches,
      LongAdder unsent,
      BooleanSupplier connected,
      Consumer<Outbound> dropped) {}

  private final Context context;
  private final BlockingQueue<Outbound> queue;
  private final Session session;
  private final MessageProducer producer;
  private final Map<Topic, jakarta.jms.Topic> destinations = new EnumMap<>(Topic.class);
  private final List<Outbound> drained = new ArrayList<>();
  private final Map<String, List<Outbound>> pending = new LinkedHashMap<>();
  private final Map<String, long[]> sequences = new HashMap<>(); // guarded by lock
  private final ReentrantLock lock = new ReentrantLock();
  private final AtomicLong queued = new AtomicLong();
  private final LogLimiter failures = new LogLimiter();
  private final LogLimiter drops = new LogLimiter();
  private final IdleStrategy retry = IdleStrategy.backoff(0, 0, RETRY, RETRY); // sender thread's
  private volatile boolean stopping;
  private volatile @Nullable Thread thread;

  JmsSender(
      Context context,
      Session session,
      MessageProducer producer,
      Function<Topic, String> topicNames)
      throws JMSException {
    this.context = context;
    this.queue = new ArrayBlockingQueue<>(context.capacity());
    this.session = session;
    this.producer = producer;
    for (Topic t : Topic.values()) {
      destinations.put(t, session.createTopic(topicNames.apply(t)));
    }
  }

  /**
   * Sends {@code o} now, on the calling thread, if it is a request, an answer or a failure of an
   * at-most-once route, the connection is up, nothing is waiting to be sent and no other thread is
   * using the session; queues it for the sender thread otherwise, applying the overflow policy if
   * the queue is full.
   *
   * @throws BufferFullException the queue is full and the policy refuses {@code o}
   * @throws InterruptedException if interrupted while a blocking policy waits for room
   */
  void submit(Outbound o) throws InterruptedException {
    if (!o.reliable()
        && isRoundTrip(o)
        && queued.get() == 0
        && context.connected().getAsBoolean()
        && lock.tryLock()) {
      try {
        if (queued.get() == 0) {
          send(List.of(o));
          return;
        }
      } finally {
        lock.unlock();
      }
    }
    queued.incrementAndGet();
    if (!queue.offer(o)) {
      queued.decrementAndGet();
      overflow(o);
    }
  }

  /** The queue is full: what the policy says. */
  private void overflow(Outbound o) throws InterruptedException {
    OverflowPolicy policy = context.policy();
    switch (policy) {
      case OverflowPolicy.Block b -> {
        // Room comes only from a broker that is there: wait for it while connected, in slices
        // that look at the connection again, and not at all while it is down.
        long left = b.timeout().toNanos();
        while (true) {
          if (!context.connected().getAsBoolean()) {
            throw full(o, "the broker is unreachable, so no room is coming");
          }
          long slice = Math.min(left, BLOCK_SLICE_NANOS);
          queued.incrementAndGet();
          if (queue.offer(o, slice, TimeUnit.NANOSECONDS)) {
            return;
          }
          queued.decrementAndGet();
          left -= slice;
          if (left <= 0) {
            throw full(o, "no room within " + b.timeout());
          }
        }
      }
      case OverflowPolicy.Reject r -> throw full(o, "policy reject");
      case OverflowPolicy.DropNewest d -> {
        if (o.reliable()) {
          throw full(o, "an at-least-once message is refused rather than dropped");
        }
        drop(o);
      }
      case OverflowPolicy.DropOldest d -> {
        if (o.reliable()) {
          throw full(o, "an at-least-once message is refused rather than dropped");
        }
        Outbound oldest = queue.poll();
        if (oldest != null) {
          queued.decrementAndGet();
          drop(oldest);
        }
        queued.incrementAndGet();
        if (!queue.offer(o)) {
          queued.decrementAndGet();
          drop(o);
        }
      }
    }
  }

  private BufferFullException full(Outbound o, String why) {
    return new BufferFullException(
        "the outbound queue of JMS transport "
            + context.node()
            + " is full ("
            + context.capacity()
            + " messages; "
            + why
            + "): "
            + o.properties().get(WireProperties.KIND)
            + " to "
            + o.properties().getOrDefault(WireProperties.TO, o.topic())
            + " not sent");
  }

  /** Counts, logs and tells the transport of a message dropped unsent. */
  private void drop(Outbound o) {
    if (o == Outbound.STOP) {
      return;
    }
    context.unsent().increment();
    long n = drops.tick();
    if (n > 0) {
      LOG.warn(
          "JMS transport {}: outbound queue full ({} messages), dropped {} on {} ({} dropped so"
              + " far)",
          context.node(),
          context.capacity(),
          o.properties().get(WireProperties.KIND),
          o.topic(),
          n);
    }
    context.dropped().accept(o);
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

  /**
   * Stops the thread at the next message (after what is queued before {@link Outbound#STOP}), and
   * stops an at-least-once sender from sending a refused message again; what it had not sent is
   * counted unsent.
   */
  void stop(Duration wait) throws InterruptedException {
    while (!queue.offer(Outbound.STOP)) {
      Outbound oldest = queue.poll();
      if (oldest != null) {
        queued.decrementAndGet();
        drop(oldest);
      }
    }
    Thread t = thread;
    if (t == null) {
      return;
    }
    long half = Math.max(1, wait.toMillis() / 2);
    t.join(half);
    stopping = true;
    LockSupport.unpark(t);
    t.join(half);
  }

  /** Wakes the sender if it waits to send a refused at-least-once message again. */
  void reconnected() {
    Thread t = thread;
    if (t != null) {
      LockSupport.unpark(t);
    }
  }

  @Override
  public void run() {
    thread = Thread.currentThread();
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
        queued.addAndGet(-drained.size());
        drained.clear();
        if (!go) {
          return;
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      for (Outbound o : queue) {
        drop(o);
      }
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
        if (!events.isEmpty() && events.get(0).reliable() != o.reliable()) {
          flush(route);
          events = pending.computeIfAbsent(route, k -> new ArrayList<>());
        }
        events.add(o);
        if (events.size() == context.maxBatch()) {
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
    if (group.size() > 1 && bytes > context.maxBytes()) {
      int half = group.size() / 2;
      send(group.subList(0, half));
      send(group.subList(half, group.size()));
      return;
    }
    // Counted before the send: the answer to a request may come back before send returns.
    int counted = counted(first) ? group.size() : 0;
    boolean reliable = first.reliable();
    String route = first.route();
    long seq = 0;
    if (route != null) {
      long[] last = sequences.computeIfAbsent(route, r -> new long[1]);
      seq = last[0] + 1;
      last[0] += group.size();
    }
    context.sent().add(counted);
    retry.reset();
    while (true) {
      try {
        producer.send(
            destinations.get(first.topic()),
            message(group, route, seq),
            reliable ? DeliveryMode.PERSISTENT : DeliveryMode.NON_PERSISTENT,
            jakarta.jms.Message.DEFAULT_PRIORITY,
            jakarta.jms.Message.DEFAULT_TIME_TO_LIVE);
        return;
      } catch (JMSException | RuntimeException e) {
        long n = failures.tick();
        if (!reliable || stopping) {
          if (reliable) {
            context.sent().add(-counted);
            context.unsent().add(counted);
          }
          if (n > 0) {
            LOG.error(
                "JMS transport {}: {} message(s) on {} not sent ({} failed sends so far): {}",
                context.node(),
                group.size(),
                first.topic(),
                n,
                e.toString());
          }
          return;
        }
        if (n > 0) {
          LOG.warn(
              "JMS transport {}: the broker did not take {} at-least-once message(s) on {}; sending"
                  + " again ({} failed sends so far): {}",
              context.node(),
              group.size(),
              first.topic(),
              n,
              e.toString());
        }
        retry.idle();
      }
    }
  }

  private BytesMessage message(List<Outbound> group, @Nullable String route, long seq)
      throws JMSException {
    Outbound first = group.get(0);
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
      context.batches().increment();
    }
    if (route != null) {
      m.setStringProperty(WireProperties.FROM, context.node());
      m.setLongProperty(WireProperties.RSEQ, seq);
      if (first.reliable()) {
        m.setBooleanProperty(WireProperties.ALO, true);
        m.setStringProperty(
            Message.HDR_DUPLICATE_DETECTION_ID.toString(),
            context.node() + "|" + route + "|" + seq);
      }
    }
    return m;
  }

  /** Whether a message counts as sent: events, requests and answers; not markers or look-ups. */
  private static boolean counted(Outbound o) {
    Object kind = o.properties().get(WireProperties.MSG);
    return kind != null && !WireProperties.MSG_LOOKUP.equals(kind);
  }
}
