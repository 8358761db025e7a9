package org.armgals.active.jms;

import static java.util.Objects.requireNonNull;

import jakarta.jms.BytesMessage;
import jakarta.jms.Connection;
import jakarta.jms.JMSException;
import jakarta.jms.JMSSecurityException;
import jakarta.jms.Message;
import jakarta.jms.MessageConsumer;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import java.time.Duration;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import org.apache.activemq.artemis.api.core.client.FailoverEventType;
import org.apache.activemq.artemis.api.jms.ActiveMQJMSConstants;
import org.apache.activemq.artemis.jms.client.ActiveMQConnection;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.ActiveException;
import org.armgals.active.Address;
import org.armgals.active.BufferFullException;
import org.armgals.active.Event;
import org.armgals.active.Filter;
import org.armgals.active.FutureValue;
import org.armgals.active.Request;
import org.armgals.active.RequestFailedException;
import org.armgals.active.Selectable;
import org.armgals.active.TimeSource;
import org.armgals.active.TransportStats;
import org.armgals.active.jms.JmsTransport.Topic;
import org.armgals.active.spi.RemoteAnswer;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@link JmsTransport} on Artemis's Jakarta client. One connection; a sender thread that owns the
 * producing session ({@link JmsSender}); per attached runtime a consuming session whose listeners
 * (one at a time, on Artemis's threads) decode, check the route and deliver, and, for the topics
 * that carry at-least-once types, a session of shared durable subscriptions in their stead; a
 * session whose synchronous consumer of answers the threads waiting for them share ({@link
 * AnswerReceiver}); one session for look-ups.
 */
final class JmsTransportImpl implements JmsTransport {
  private static final Logger LOG = LoggerFactory.getLogger(JmsTransportImpl.class);

  /**
   * How the transport's own sessions consume (answers, look-ups, the at-most-once events and
   * requests of the attached runtimes): pre-acknowledged, Artemis's mode in which the broker
   * acknowledges a message as it delivers it and the client sends no acknowledgement back (decision
   * 0034). The messages are non-persistent on subscriptions that live as long as their consumer, so
   * an acknowledgement buys nothing; sent, it would go ahead of the answer on the connection.
   * At-least-once subscriptions acknowledge each message once it is delivered (decision 0042).
   */
  private static final int CONSUMING = ActiveMQJMSConstants.PRE_ACKNOWLEDGE;

  private static final Duration STOP_WAIT = Duration.ofSeconds(10);

  /** The most events a message may carry: the largest {@link Builder#maxBatch}. */
  private static final int MAX_BATCH = 4096;

  /** The sessions of one attached runtime and the ledger of its inbound routes. */
  private record Attached(Session session, @Nullable Session durable, RouteLedger ledger) {}

  private final @Nullable EmbeddedBroker ownBroker;
  private final String url;
  private final String prefix;
  private final WireCodec codec;
  private final Map<Class<?>, Topic> topics;
  private final Map<Class<?>, Boolean> reliableTypes;
  private final Set<Topic> reliableTopics;
  private final boolean jmsEverywhere;
  private final String node = UUID.randomUUID().toString();
  private final ActiveMQConnectionFactory factory;
  private final Connection connection;
  private final AnswerReceiver answers;
  private final @Nullable String answerSubscription;
  private final Session answerSession;
  private final MessageConsumer answerConsumer;
  private final RouteLedger answerRoutes = new RouteLedger();
  private final Map<String, Attached> runtimes = new ConcurrentHashMap<>();
  private final Map<String, Address> names = new ConcurrentHashMap<>();
  private final Set<JmsSubscription> subscriptions = ConcurrentHashMap.newKeySet();
  private final AtomicLong subscriptionIds = new AtomicLong();
  private final PendingAnswers pending;
  private final TimeSource time;
  private final Thread sender;
  private final JmsSender sending;
  private final ScheduledExecutorService sweeper;
  private final AtomicLong seq = new AtomicLong();
  private final LongAdder sent = new LongAdder();
  private final LongAdder received = new LongAdder();
  private final LongAdder batches = new LongAdder();
  private final LongAdder rejected = new LongAdder();
  private final LongAdder lost = new LongAdder();
  private final LongAdder duplicates = new LongAdder();
  private final LongAdder unmatched = new LongAdder();
  private final LongAdder unsent = new LongAdder();
  private final LogLimiter rejections = new LogLimiter();
  private final LogLimiter refusals = new LogLimiter();
  private final LogLimiter gaps = new LogLimiter();
  private final LogLimiter strays = new LogLimiter();
  private final LogLimiter lostAnswers = new LogLimiter();
  private final LogLimiter outages = new LogLimiter();
  private final AtomicBoolean closed = new AtomicBoolean();
  private volatile boolean connected = true;

  private JmsTransportImpl(JmsTransport.Builder b, @Nullable EmbeddedBroker ownBroker, String url)
      throws JMSException {
    this.ownBroker = ownBroker;
    this.url = url;
    this.prefix = b.prefix;
    this.codec = new WireCodec(b.allowed, b.maxMessageBytes);
    this.topics = new HashMap<>(b.topics);
    this.reliableTypes = new HashMap<>();
    Set<Topic> durable = EnumSet.noneOf(Topic.class);
    for (Class<?> t : b.allowed) {
      if (!Event.class.isAssignableFrom(t)) {
        continue;
      }
      Topic topic = b.topics.getOrDefault(t, Topic.ENTITY);
      Guarantee g =
          b.typeGuarantees.getOrDefault(
              t, b.topicGuarantees.getOrDefault(topic, Guarantee.AT_MOST_ONCE));
      if (g == Guarantee.AT_LEAST_ONCE) {
        reliableTypes.put(t, true);
        durable.add(topic);
      }
    }
    this.reliableTopics = durable;
    this.jmsEverywhere = b.jmsEverywhere;
    this.time = b.timeSource;
    this.pending = new PendingAnswers(b.timeSource, b.replyTimeout);
    this.factory = new ActiveMQConnectionFactory(url);
    this.connection =
        b.user != null ? factory.createConnection(b.user, b.password) : factory.createConnection();
    connection.setExceptionListener(
        e -> {
          if (outages.tick() > 0) {
            LOG.warn("JMS transport {}: connection to {} failed; reconnecting", node, url, e);
          }
        });
    ((ActiveMQConnection) connection).setFailoverListener(this::onFailover);
    this.answerSession = connection.createSession(false, CONSUMING);
    String answersFor = WireProperties.NODE + " = " + WireProperties.literal(node);
    jakarta.jms.Topic future = answerSession.createTopic(topicName(Topic.FUTURE));
    if (reliableTypes.isEmpty()) {
      this.answerSubscription = null;
      this.answerConsumer = answerSession.createConsumer(future, answersFor);
    } else {
      this.answerSubscription = prefix + ":answers:" + node;
      this.answerConsumer =
          answerSession.createSharedDurableConsumer(future, answerSubscription, answersFor);
    }
    this.answers =
        new AnswerReceiver(
            answerConsumer,
            this::onAnswer,
            pending::size,
            () -> connected,
            time,
            node.substring(0, 8));
    Session lookupSession = connection.createSession(false, CONSUMING);
    MessageConsumer lookups =
        lookupSession.createConsumer(lookupSession.createTopic(topicName(Topic.NAMES)));
    lookups.setMessageListener(this::onLookup);
    JmsSender.Context context =
        new JmsSender.Context(
            node,
            b.outboundCapacity,
            b.outboundPolicy,
            b.maxBatch,
            b.maxMessageBytes,
            sent,
            batches,
            unsent,
            () -> connected,
            this::droppedUnsent);
    Session producing = connection.createSession(false, Session.AUTO_ACKNOWLEDGE);
    MessageProducer producer = producing.createProducer(null);
    producer.setDisableMessageID(true);
    producer.setDisableMessageTimestamp(true);
    this.sending = new JmsSender(context, producing, producer, this::topicName);
    this.sender =
        Thread.ofPlatform()
            .name("armgals-jms-sender-" + node.substring(0, 8))
            .daemon(true)
            .unstarted(sending);
    long period = Math.max(10, Math.min(1_000, b.replyTimeout.toMillis() / 4));
    this.sweeper =
        Executors.newSingleThreadScheduledExecutor(
            r -> Thread.ofPlatform().name("armgals-jms-timeouts").daemon(true).unstarted(r));
    sweeper.scheduleAtFixedRate(
        () -> {
          pending.expire();
          answers.nudge();
        },
        period,
        period,
        TimeUnit.MILLISECONDS);
    sender.start();
    connection.start();
    answers.start();
  }

  static JmsTransport connect(JmsTransport.Builder b) {
    EmbeddedBroker own = null;
    String base = b.url;
    if (base == null) {
      own = b.nettyPort > 0 ? EmbeddedBroker.start(b.nettyPort) : EmbeddedBroker.start();
      base = own.inVmUrl();
    }
    String url = withOptions(base, b.options);
    try {
      return new JmsTransportImpl(b, own, url);
    } catch (JMSSecurityException e) {
      throw new IllegalStateException(
          "broker "
              + base
              + " refused the login of the JMS transport ("
              + (b.user == null
                  ? "no user given; use JmsTransport.builder().broker(url, user, password)"
                  : "user '" + b.user + "' and its password")
              + "): "
              + e.getMessage(),
          e);
    } catch (JMSException | RuntimeException e) {
      if (own != null) {
        own.close();
      }
      if (e instanceof IllegalArgumentException iae) {
        throw iae;
      }
      throw new IllegalStateException("cannot connect the JMS transport to " + url + ": " + e, e);
    }
  }

  private static String withOptions(String url, Map<String, String> options) {
    Map<String, String> all = new LinkedHashMap<>(options);
    if (!url.contains("reconnectAttempts=")) {
      all.putIfAbsent("reconnectAttempts", "-1");
    }
    StringBuilder s = new StringBuilder(url);
    char sep = url.contains("?") ? '&' : '?';
    for (Map.Entry<String, String> e : all.entrySet()) {
      s.append(sep).append(e.getKey()).append('=').append(e.getValue());
      sep = '&';
    }
    return s.toString();
  }

  private void onFailover(FailoverEventType event) {
    switch (event) {
      case FAILURE_DETECTED -> connected = false;
      case FAILOVER_COMPLETED -> {
        connected = true;
        sending.reconnected();
        LOG.info("JMS transport {}: reconnected to {}", node, url);
      }
      case FAILOVER_FAILED -> LOG.error("JMS transport {}: reconnection to {} failed", node, url);
    }
  }

  // ------------------------------------------------------------------ Transport

  @Override
  public void attach(String runtime, Inbound inbound) {
    requireNonNull(runtime, "runtime");
    requireNonNull(inbound, "inbound");
    checkOpen();
    Session session = null;
    Session durable = null;
    try {
      session = connection.createSession(false, CONSUMING);
      durable =
          reliableTopics.isEmpty()
              ? null
              : connection.createSession(false, Session.AUTO_ACKNOWLEDGE);
      Attached attached = new Attached(session, durable, new RouteLedger());
      if (runtimes.putIfAbsent(runtime, attached) != null) {
        session.close();
        if (durable != null) {
          durable.close();
        }
        throw new IllegalStateException("a runtime named '" + runtime + "' is already attached");
      }
      String to = WireProperties.TO + " = " + WireProperties.literal(runtime);
      for (Topic t : List.of(Topic.ENTITY, Topic.SMETA, Topic.BMETA)) {
        // A topic with at-least-once types is taken whole from a durable subscription, so that
        // its routes keep their order whatever each message's guarantee.
        MessageConsumer c =
            durable != null && reliableTopics.contains(t)
                ? durable.createSharedDurableConsumer(
                    durable.createTopic(topicName(t)), prefix + ":" + runtime + ":" + t.name(), to)
                : session.createConsumer(session.createTopic(topicName(t)), to);
        c.setMessageListener(m -> onInbound(runtime, inbound, attached, t, m));
      }
    } catch (JMSException e) {
      runtimes.remove(runtime);
      closeQuietly(session);
      closeQuietly(durable);
      throw new IllegalStateException("cannot subscribe runtime " + runtime + " on " + url, e);
    }
  }

  private void closeQuietly(@Nullable Session s) {
    if (s != null) {
      try {
        s.close();
      } catch (JMSException e) {
        LOG.warn("JMS transport {}: closing a session failed", node, e);
      }
    }
  }

  /**
   * {@inheritDoc}
   *
   * <p>The durable subscriptions of its at-least-once topics stay on the broker, so that what is
   * sent to the runtime while it is away waits for it.
   */
  @Override
  public void detach(String runtime) {
    Attached a = runtimes.remove(requireNonNull(runtime, "runtime"));
    if (a != null) {
      closeQuietly(a.session());
      closeQuietly(a.durable());
    }
  }

  private boolean reliable(Class<?> type) {
    return reliableTypes.containsKey(type);
  }

  @Override
  public void send(Address destination, Event event) {
    requireNonNull(destination, "destination");
    requireNonNull(event, "event");
    Map<String, Object> props = selectorProperties(event);
    props.put(WireProperties.MSG, WireProperties.MSG_EVENT);
    props.put(WireProperties.TO, destination.runtime());
    Topic topic = topics.getOrDefault(event.getClass(), Topic.ENTITY);
    boolean rel = reliable(event.getClass());
    enqueue(
        new Outbound(
            topic,
            Outbound.route(topic, destination.runtime()),
            true,
            encode(event),
            props,
            rel,
            0));
  }

  @Override
  @SuppressWarnings("unchecked")
  public <R extends @Nullable Object> FutureValue<R> ask(Address destination, Request<R> request) {
    requireNonNull(destination, "destination");
    requireNonNull(request, "request");
    Map<String, Object> props = selectorProperties(request);
    byte[] value = encode(request);
    RemoteAnswer<Object> future = FutureValue.remote(destination.toString(), time, answers);
    long corr = pending.open(future, destination.toString(), destination.runtime());
    props.put(WireProperties.MSG, WireProperties.MSG_REQUEST);
    props.put(WireProperties.TO, destination.runtime());
    props.put(WireProperties.NODE, node);
    props.put(WireProperties.CORR, corr);
    Topic topic = topics.getOrDefault(request.getClass(), Topic.ENTITY);
    boolean rel = reliable(request.getClass());
    try {
      enqueue(
          new Outbound(
              topic, Outbound.route(topic, destination.runtime()), false, value, props, rel, corr));
    } catch (RuntimeException refused) {
      pending.take(corr);
      throw refused;
    }
    return (FutureValue<R>) future;
  }

  @Override
  public int failRequestsTo(String runtime, String why) {
    requireNonNull(runtime, "runtime");
    requireNonNull(why, "why");
    return pending.failRuntime(
        runtime,
        new ActiveException(
            "runtime '" + runtime + "' " + why + " before answering (JMS transport " + node + ")"));
  }

  /** A message the outbound queue dropped: a request's future fails at once. */
  private void droppedUnsent(Outbound o) {
    if (o.corr() != 0) {
      RemoteAnswer<Object> f = pending.take(o.corr());
      if (f != null) {
        f.abandon(
            new BufferFullException(
                "the request was dropped unsent: the outbound queue of JMS transport "
                    + node
                    + " is full"));
      }
    }
  }

  @Override
  public boolean routesLocalEvents() {
    return jmsEverywhere;
  }

  @Override
  public TransportStats stats() {
    return new TransportStats(
        sent.sum(),
        received.sum(),
        batches.sum(),
        rejected.sum(),
        lost.sum(),
        duplicates.sum(),
        unmatched.sum(),
        unsent.sum());
  }

  // ------------------------------------------------------------------ publish and subscribe

  private static void checkPublishable(Topic topic) {
    requireNonNull(topic, "topic");
    if (topic == Topic.FUTURE || topic == Topic.NAMES) {
      throw new IllegalArgumentException(
          "events are published on ENTITY, SMETA or BMETA, not " + topic);
    }
  }

  @Override
  public void publish(Topic topic, Event event) {
    checkPublishable(topic);
    requireNonNull(event, "event");
    Map<String, Object> props = selectorProperties(event);
    byte[] value = encode(event);
    for (JmsSubscription s : subscriptions) {
      if (s.topic() == topic) {
        s.local(event, props);
      }
    }
    Map<String, Object> wire = new HashMap<>(props);
    wire.put(WireProperties.MSG, WireProperties.MSG_PUBLISH);
    wire.put(WireProperties.FROM, node);
    enqueue(new Outbound(topic, null, false, value, wire));
  }

  @Override
  public Subscription subscribe(
      Topic topic, Filter filter, java.util.function.Consumer<? super Event> handler) {
    checkPublishable(topic);
    requireNonNull(filter, "filter");
    requireNonNull(handler, "handler");
    checkOpen();
    try {
      JmsSubscription s =
          new JmsSubscription(
              this, topic, node + "/" + subscriptionIds.incrementAndGet(), filter, handler);
      subscriptions.add(s);
      return s;
    } catch (JMSException e) {
      throw new IllegalStateException("cannot subscribe to " + topicName(topic) + " on " + url, e);
    }
  }

  String node() {
    return node;
  }

  /** Whether the connection is up, as Artemis's failover events last said. */
  boolean connected() {
    return connected;
  }

  Connection connection() {
    return connection;
  }

  AnswerReceiver answers() {
    return answers;
  }

  int awaitedAnswers() {
    return pending.size();
  }

  void forget(JmsSubscription s) {
    subscriptions.remove(s);
  }

  void publishMarker(Topic topic, String subscription) {
    Map<String, Object> props = new HashMap<>();
    props.put(WireProperties.MARKER, subscription);
    enqueue(new Outbound(topic, null, false, codec.encodeValue(null), props));
  }

  /** A published event from the broker; null (counted, logged) if it is not a good one. */
  @Nullable Event decodePublished(Message m) {
    try {
      if (!(m.getObjectProperty(WireProperties.FROM) instanceof String)
          || !(m.getObjectProperty(WireProperties.SEQ) instanceof Long)) {
        throw new WireFormatException(
            "a published event needs " + WireProperties.FROM + " and " + WireProperties.SEQ);
      }
      List<@Nullable Object> values = decode(m);
      if (values.size() != 1 || !(values.get(0) instanceof Event e)) {
        throw new WireFormatException("a published message must hold one event: " + values);
      }
      received.increment();
      return e;
    } catch (WireFormatException | JMSException | RuntimeException e) {
      reject(m, e);
      return null;
    }
  }

  void rejectPublished(Exception e) {
    reject(null, e);
  }

  // ------------------------------------------------------------------ names

  @Override
  public String topicName(Topic topic) {
    return prefix + "/" + requireNonNull(topic, "topic").path();
  }

  @Override
  public String brokerUrl() {
    return url;
  }

  @Override
  public java.util.Optional<EmbeddedBroker> embeddedBroker() {
    return java.util.Optional.ofNullable(ownBroker);
  }

  @Override
  public void register(String name, Address address) {
    requireNonNull(name, "name");
    requireNonNull(address, "address");
    if (name.isBlank()) {
      throw new IllegalArgumentException("name must not be blank, was '" + name + "'");
    }
    names.put(name, address);
  }

  @Override
  public void unregister(String name) {
    names.remove(requireNonNull(name, "name"));
  }

  @Override
  @SuppressWarnings("unchecked")
  public FutureValue<Address> lookup(String name) {
    requireNonNull(name, "name");
    Address here = names.get(name);
    if (here != null) {
      return FutureValue.completed(here);
    }
    String service = "the name service (name '" + name + "')";
    RemoteAnswer<Object> future = FutureValue.remote(service, time, answers);
    long corr = pending.open(future, service, null);
    Map<String, Object> props = new HashMap<>();
    props.put(WireProperties.MSG, WireProperties.MSG_LOOKUP);
    props.put(WireProperties.NAME, name);
    props.put(WireProperties.NODE, node);
    props.put(WireProperties.CORR, corr);
    enqueue(new Outbound(Topic.NAMES, null, false, codec.encodeValue(null), props));
    return (FutureValue<Address>) (FutureValue<?>) future;
  }

  // ------------------------------------------------------------------ sending

  private Map<String, Object> selectorProperties(Event event) {
    Map<String, Object> props = new HashMap<>();
    if (event instanceof Selectable s) {
      Map<String, ?> own = s.selectorProperties();
      WireProperties.checkUserProperties(event, own);
      props.putAll(own);
    }
    props.put(WireProperties.KIND, event.getClass().getSimpleName());
    Address from = event.sender();
    if (from != null) {
      props.put(WireProperties.SENDER, from.toString());
    }
    props.put(WireProperties.DESTINATION, event.destination().toString());
    props.put(WireProperties.SEQ, seq.incrementAndGet());
    return props;
  }

  private byte[] encode(Object value) {
    if (!codec.allows(value.getClass())) {
      throw new IllegalArgumentException(
          value.getClass().getName()
              + " is not on this transport's allow-list; add it with"
              + " JmsTransport.builder().allow(...)");
    }
    byte[] bytes = codec.encodeValue(value);
    if (bytes.length + 5 > codec.maxBytes()) {
      throw new IllegalArgumentException(
          value.getClass().getName()
              + " encodes to "
              + bytes.length
              + " bytes, over the limit of "
              + codec.maxBytes());
    }
    return bytes;
  }

  private void enqueue(Outbound o) {
    checkOpen();
    try {
      sending.submit(o);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new ActiveException("interrupted while the JMS transport's send queue was full");
    }
  }

  private void checkOpen() {
    if (closed.get()) {
      throw new IllegalStateException("JMS transport " + node + " is closed");
    }
  }

  // ------------------------------------------------------------------ receiving

  /**
   * An event, a batch or a request for the runtime {@code runtime}, on {@code topic}. Its place on
   * its route is taken first (a message that arrived counts as arrived, whatever its body), then it
   * is checked whole before anything is delivered, so that each message lands in one count: its
   * events received (or refused by their object), or the message rejected, or its events
   * duplicates.
   */
  private void onInbound(
      String runtime, Inbound inbound, Attached attached, Topic topic, Message m) {
    try {
      int count = m.propertyExists(WireProperties.COUNT) ? requiredInt(m, WireProperties.COUNT) : 1;
      int skip = route(attached.ledger(), inbound, topic, m, count);
      if (skip == count) {
        return;
      }
      String kind = required(m, WireProperties.MSG);
      List<@Nullable Object> values = decode(m);
      switch (kind) {
        case WireProperties.MSG_EVENT, WireProperties.MSG_BATCH -> {
          if (values.size() != count) {
            throw new WireFormatException(
                "a message of " + count + " event(s) holds " + values.size() + " value(s)");
          }
          List<Event> events = new ArrayList<>(values.size());
          for (Object v : values) {
            events.add(event(runtime, v));
          }
          for (int i = skip; i < events.size(); i++) {
            deliver(runtime, inbound, events.get(i));
          }
        }
        case WireProperties.MSG_REQUEST -> {
          String replyTo = required(m, WireProperties.NODE);
          long corr = requiredLong(m, WireProperties.CORR);
          if (values.size() != 1 || !(values.get(0) instanceof Request<?> r)) {
            throw new WireFormatException("a request message must hold one Request: " + values);
          }
          ask(
              runtime,
              inbound,
              event(runtime, r),
              r,
              replyTo,
              corr,
              m.propertyExists(WireProperties.ALO));
        }
        default ->
            throw new WireFormatException("unknown " + WireProperties.MSG + " '" + kind + "'");
      }
    } catch (WireFormatException | JMSException | RuntimeException e) {
      reject(m, e);
    }
  }

  /**
   * Takes a message's place on its route (sender, topic, guarantee): counts and tells the gap
   * before it, counts the events of it taken already, and returns how many to skip.
   *
   * @param inbound the runtime to tell of a gap; null: answers to this transport
   */
  private int route(
      RouteLedger ledger, @Nullable Inbound inbound, Topic topic, Message m, int count)
      throws JMSException, WireFormatException {
    String from = required(m, WireProperties.FROM);
    long first = requiredLong(m, WireProperties.RSEQ);
    if (first < 1 || count < 1 || count > MAX_BATCH) {
      throw new WireFormatException(
          WireProperties.RSEQ
              + " must be >= 1 and "
              + WireProperties.COUNT
              + " in [1, "
              + MAX_BATCH
              + "], were "
              + first
              + " and "
              + count);
    }
    String route = from + "|" + topic.path();
    RouteLedger.Verdict v = ledger.take(route, first, count);
    if (v.lost() > 0) {
      lost.add(v.lost());
      long n = gaps.tick();
      if (n > 0) {
        LOG.warn(
            "JMS transport {}: {} message(s) of route {} never arrived (gaps so far: {})",
            node,
            v.lost(),
            route,
            n);
      }
      if (inbound != null) {
        inbound.lost(route, v.lost());
      }
    }
    if (v.skip() > 0) {
      duplicates.add(v.skip());
    }
    return v.skip();
  }

  private void deliver(String runtime, Inbound inbound, Event e) {
    try {
      inbound.deliver(e.destination(), e);
      received.increment();
    } catch (ActiveException refused) {
      rejected.increment();
      long n = refusals.tick();
      if (n > 0) {
        LOG.warn(
            "JMS transport {}: runtime {} refused {} ({} refused so far): {}",
            node,
            runtime,
            e,
            n,
            refused.toString());
      }
    }
  }

  private void ask(
      String runtime,
      Inbound inbound,
      Event e,
      Request<?> r,
      String replyTo,
      long corr,
      boolean reliable) {
    received.increment();
    try {
      inbound.ask(
          e.destination(), r, (value, failure) -> answer(replyTo, corr, value, failure, reliable));
    } catch (ActiveException | UnsupportedOperationException refused) {
      answer(replyTo, corr, null, refused, reliable);
    }
  }

  private static Event event(String runtime, @Nullable Object v) throws WireFormatException {
    if (!(v instanceof Event e)) {
      throw new WireFormatException(
          "expected an event, got " + (v == null ? "null" : v.getClass().getName()));
    }
    Address to = e.destination();
    if (to == null) {
      throw new WireFormatException("event " + e + " has no destination");
    }
    if (!to.runtime().equals(runtime)) {
      throw new WireFormatException(
          "event "
              + e
              + " is addressed to "
              + e.destination()
              + ", but came to runtime "
              + runtime);
    }
    return e;
  }

  /**
   * Sends the answer of a request (or look-up) back to the node that waits for it, with the
   * request's guarantee. Never throws: it runs on the thread that completed the request, an
   * object's worker among them; an answer that cannot be sent is logged, and its future fails at
   * its reply timeout.
   */
  private void answer(
      String node,
      long corr,
      @Nullable Object value,
      @Nullable Throwable failure,
      boolean reliable) {
    if (closed.get()) {
      return;
    }
    try {
      enqueue(answerMessage(node, corr, value, failure, reliable));
    } catch (RuntimeException e) {
      long n = lostAnswers.tick();
      if (n > 0) {
        LOG.warn(
            "JMS transport {}: the answer to request {} of {} is lost ({} so far)",
            this.node,
            corr,
            node,
            n,
            e);
      }
    }
  }

  private Outbound answerMessage(
      String node,
      long corr,
      @Nullable Object value,
      @Nullable Throwable failure,
      boolean reliable) {
    Map<String, Object> props = new HashMap<>();
    props.put(WireProperties.NODE, node);
    props.put(WireProperties.CORR, corr);
    byte[] body;
    Throwable cause = failure;
    while (cause instanceof CompletionException || cause instanceof RequestFailedException) {
      if (cause.getCause() == null) {
        break;
      }
      cause = cause.getCause();
    }
    if (cause == null) {
      try {
        body = codec.encodeValue(value);
        props.put(WireProperties.MSG, WireProperties.MSG_ANSWER);
      } catch (IllegalArgumentException notAllowed) {
        cause = notAllowed;
        body = codec.encodeValue(null);
      }
    } else {
      body = codec.encodeValue(null);
    }
    if (cause != null) {
      String text = cause.toString();
      props.put(WireProperties.MSG, WireProperties.MSG_FAILURE);
      props.put(WireProperties.ERROR, text.length() > 1_000 ? text.substring(0, 1_000) : text);
    }
    return new Outbound(
        Topic.FUTURE, Outbound.route(Topic.FUTURE, node), false, body, props, reliable, 0);
  }

  /**
   * An answer to one of this transport's requests or look-ups, checked whole first; one that no
   * request waits for (late, repeated, or of a number never given) is counted unmatched.
   */
  private void onAnswer(Message m) {
    try {
      if (route(answerRoutes, null, Topic.FUTURE, m, 1) > 0) {
        return;
      }
      String kind = required(m, WireProperties.MSG);
      long corr = requiredLong(m, WireProperties.CORR);
      String error =
          switch (kind) {
            case WireProperties.MSG_ANSWER -> null;
            case WireProperties.MSG_FAILURE -> required(m, WireProperties.ERROR);
            default -> throw new WireFormatException("unknown answer kind '" + kind + "'");
          };
      List<@Nullable Object> values = decode(m);
      if (values.size() != 1) {
        throw new WireFormatException("an answer must hold one value, not " + values.size());
      }
      RemoteAnswer<Object> f = pending.take(corr);
      if (f == null) {
        unmatched.increment();
        long n = strays.tick();
        if (n > 0) {
          LOG.info(
              "JMS transport {}: an answer nobody waits for (number {}; late, repeated or unknown;"
                  + " {} so far)",
              node,
              corr,
              n);
        }
        return;
      }
      received.increment();
      if (error == null) {
        f.complete(values.get(0));
      } else {
        f.fail(new ActiveException("failed remotely: " + error));
      }
    } catch (WireFormatException | JMSException | RuntimeException e) {
      reject(m, e);
    }
  }

  /** A look-up from any transport: answered if this one holds the name. */
  private void onLookup(Message m) {
    try {
      if (!WireProperties.MSG_LOOKUP.equals(required(m, WireProperties.MSG))) {
        throw new WireFormatException("not a look-up");
      }
      String from = required(m, WireProperties.NODE);
      long corr = requiredLong(m, WireProperties.CORR);
      Address a = names.get(required(m, WireProperties.NAME));
      if (a != null && !from.equals(node)) {
        answer(from, corr, a, null, false);
      }
    } catch (WireFormatException | JMSException | RuntimeException e) {
      reject(m, e);
    }
  }

  private List<@Nullable Object> decode(Message m) throws JMSException, WireFormatException {
    if (!(m instanceof BytesMessage b)) {
      throw new WireFormatException("expected a BytesMessage, got " + m.getClass().getSimpleName());
    }
    long length = b.getBodyLength();
    if (length > codec.maxBytes()) {
      throw new WireFormatException(
          "message of " + length + " bytes is over the limit of " + codec.maxBytes());
    }
    byte[] body = new byte[(int) length];
    b.readBytes(body);
    return codec.decode(body);
  }

  private static String required(Message m, String property)
      throws JMSException, WireFormatException {
    Object v = m.getObjectProperty(property);
    if (v == null) {
      throw new WireFormatException("missing property " + property);
    }
    return v.toString();
  }

  private static int requiredInt(Message m, String property)
      throws JMSException, WireFormatException {
    if (!(m.getObjectProperty(property) instanceof Integer v)) {
      throw new WireFormatException("property " + property + " missing or not an int");
    }
    return v;
  }

  private static long requiredLong(Message m, String property)
      throws JMSException, WireFormatException {
    if (!(m.getObjectProperty(property) instanceof Long v)) {
      throw new WireFormatException("property " + property + " missing or not a long");
    }
    return v;
  }

  /** Counts and logs a dead letter, at the rate of a {@link LogLimiter}. */
  private void reject(@Nullable Message m, Exception why) {
    rejected.increment();
    long n = rejections.tick();
    if (n > 0) {
      LOG.error(
          "JMS transport {}: message rejected (dead letters so far: {}): {}",
          node,
          n,
          why.toString());
    }
  }

  // ------------------------------------------------------------------ close

  @Override
  public void close() {
    if (!closed.compareAndSet(false, true)) {
      return;
    }
    try {
      // While the broker is away a sender may be stuck in a send: wait for it briefly only.
      Duration wait = connected ? STOP_WAIT : Duration.ofMillis(200);
      sending.stop(wait);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    sweeper.shutdownNow();
    for (JmsSubscription s : List.copyOf(subscriptions)) {
      s.close();
    }
    pending.abandonAll(new ActiveException("JMS transport " + node + " closed before the answer"));
    answers.close();
    String subscription = answerSubscription;
    if (subscription != null) {
      try {
        answerConsumer.close();
        answerSession.unsubscribe(subscription);
      } catch (JMSException e) {
        LOG.warn("JMS transport {}: removing its subscription to answers failed", node, e);
      }
    }
    try {
      connection.close();
    } catch (JMSException e) {
      LOG.warn("JMS transport {}: closing the connection failed", node, e);
    }
    factory.close();
    if (ownBroker != null) {
      ownBroker.close();
    }
  }

  @Override
  public String toString() {
    return "JmsTransport[" + url + ", " + prefix + ", runtimes " + runtimes.keySet() + "]";
  }
}
