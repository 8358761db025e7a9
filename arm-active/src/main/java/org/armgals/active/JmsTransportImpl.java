package org.armgals.active;

import static java.util.Objects.requireNonNull;

import jakarta.jms.BytesMessage;
import jakarta.jms.Connection;
import jakarta.jms.JMSException;
import jakarta.jms.Message;
import jakarta.jms.MessageConsumer;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import org.apache.activemq.artemis.api.jms.ActiveMQJMSConstants;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.JmsTransport.Topic;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@link JmsTransport} on Artemis's Jakarta client. One connection; a sender thread that owns the
 * producing session and batches; per attached runtime a consuming session whose listeners (one at a
 * time, on Artemis's threads) decode and deliver; a session whose synchronous consumer of answers
 * the threads waiting for them share ({@link AnswerReceiver}); one session for look-ups.
 */
final class JmsTransportImpl implements JmsTransport {
  private static final Logger LOG = LoggerFactory.getLogger(JmsTransportImpl.class);

  /**
   * How the transport's own sessions consume (answers, look-ups, the events and requests of the
   * attached runtimes): pre-acknowledged, Artemis's mode in which the broker acknowledges a message
   * as it delivers it and the client sends no acknowledgement back (decision 0034). The messages
   * are non-persistent on subscriptions that live as long as their consumer, so an acknowledgement
   * buys nothing; sent, it would go ahead of the answer on the connection.
   */
  private static final int CONSUMING = ActiveMQJMSConstants.PRE_ACKNOWLEDGE;

  private static final int QUEUE = 16_384;
  private static final int LOGGED_REJECTIONS = 20;

  private final @Nullable EmbeddedBroker ownBroker;
  private final String url;
  private final String prefix;
  private final WireCodec codec;
  private final Map<Class<?>, Topic> topics;
  private final boolean jmsEverywhere;
  private final String node = UUID.randomUUID().toString();
  private final ActiveMQConnectionFactory factory;
  private final Connection connection;
  private final AnswerReceiver answers;
  private final Map<String, Session> runtimes = new ConcurrentHashMap<>();
  private final Map<String, Address> names = new ConcurrentHashMap<>();
  private final Set<JmsSubscription> subscriptions = ConcurrentHashMap.newKeySet();
  private final AtomicLong subscriptionIds = new AtomicLong();
  private final PendingAnswers pending;
  private final TimeSource time;
  private final BlockingQueue<Outbound> outbound = new ArrayBlockingQueue<>(QUEUE);
  private final Thread sender;
  private final JmsSender sending;
  private final ScheduledExecutorService sweeper;
  private final AtomicLong seq = new AtomicLong();
  private final LongAdder sent = new LongAdder();
  private final LongAdder received = new LongAdder();
  private final LongAdder batches = new LongAdder();
  private final LongAdder rejected = new LongAdder();
  private final AtomicBoolean closed = new AtomicBoolean();

  private JmsTransportImpl(JmsTransport.Builder b, @Nullable EmbeddedBroker ownBroker, String url)
      throws JMSException {
    this.ownBroker = ownBroker;
    this.url = url;
    this.prefix = b.prefix;
    this.codec = new WireCodec(b.allowed, b.maxMessageBytes);
    this.topics = new HashMap<>(b.topics);
    this.jmsEverywhere = b.jmsEverywhere;
    this.time = b.timeSource;
    this.pending = new PendingAnswers(b.timeSource, b.replyTimeout);
    this.factory = new ActiveMQConnectionFactory(url);
    this.connection =
        b.user != null ? factory.createConnection(b.user, b.password) : factory.createConnection();
    connection.setExceptionListener(
        e -> LOG.warn("JMS transport {}: connection to {} failed; reconnecting", node, url, e));
    Session answerSession = connection.createSession(false, CONSUMING);
    this.answers =
        new AnswerReceiver(
            answerSession.createConsumer(
                answerSession.createTopic(topicName(Topic.FUTURE)),
                WireProperties.NODE + " = " + WireProperties.literal(node)),
            this::onAnswer,
            pending::size,
            time,
            node.substring(0, 8));
    Session lookupSession = connection.createSession(false, CONSUMING);
    MessageConsumer lookups =
        lookupSession.createConsumer(lookupSession.createTopic(topicName(Topic.NAMES)));
    lookups.setMessageListener(this::onLookup);
    Session producing = connection.createSession(false, Session.AUTO_ACKNOWLEDGE);
    MessageProducer producer = producing.createProducer(null);
    producer.setDeliveryMode(jakarta.jms.DeliveryMode.NON_PERSISTENT);
    producer.setDisableMessageID(true);
    producer.setDisableMessageTimestamp(true);
    this.sending =
        new JmsSender(
            outbound,
            producing,
            producer,
            this::topicName,
            b.maxBatch,
            b.maxMessageBytes,
            sent,
            batches,
            node);
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

  // ------------------------------------------------------------------ Transport

  @Override
  public void attach(String runtime, Inbound inbound) {
    requireNonNull(runtime, "runtime");
    requireNonNull(inbound, "inbound");
    checkOpen();
    try {
      Session session = connection.createSession(false, CONSUMING);
      if (runtimes.putIfAbsent(runtime, session) != null) {
        session.close();
        throw new IllegalStateException("a runtime named '" + runtime + "' is already attached");
      }
      String selector = WireProperties.TO + " = " + WireProperties.literal(runtime);
      for (Topic t : List.of(Topic.ENTITY, Topic.SMETA, Topic.BMETA)) {
        MessageConsumer c = session.createConsumer(session.createTopic(topicName(t)), selector);
        c.setMessageListener(m -> onInbound(runtime, inbound, m));
      }
    } catch (JMSException e) {
      runtimes.remove(runtime);
      throw new IllegalStateException("cannot subscribe runtime " + runtime + " on " + url, e);
    }
  }

  @Override
  public void detach(String runtime) {
    Session s = runtimes.remove(requireNonNull(runtime, "runtime"));
    if (s != null) {
      try {
        s.close();
      } catch (JMSException e) {
        LOG.warn("JMS transport {}: closing the session of runtime {} failed", node, runtime, e);
      }
    }
  }

  @Override
  public void send(Address destination, Event event) {
    requireNonNull(destination, "destination");
    requireNonNull(event, "event");
    Map<String, Object> props = selectorProperties(event);
    props.put(WireProperties.MSG, WireProperties.MSG_EVENT);
    props.put(WireProperties.TO, destination.runtime());
    Topic topic = topics.getOrDefault(event.getClass(), Topic.ENTITY);
    enqueue(
        new Outbound(
            topic, Outbound.route(topic, destination.runtime()), true, encode(event), props));
  }

  @Override
  @SuppressWarnings("unchecked")
  public <R extends @Nullable Object> FutureValue<R> ask(Address destination, Request<R> request) {
    requireNonNull(destination, "destination");
    requireNonNull(request, "request");
    Map<String, Object> props = selectorProperties(request);
    byte[] value = encode(request);
    ValueFuture<Object> future = ValueFuture.remote(destination.toString(), time, answers);
    long corr = pending.open(future, destination.toString());
    props.put(WireProperties.MSG, WireProperties.MSG_REQUEST);
    props.put(WireProperties.TO, destination.runtime());
    props.put(WireProperties.NODE, node);
    props.put(WireProperties.CORR, corr);
    Topic topic = topics.getOrDefault(request.getClass(), Topic.ENTITY);
    enqueue(new Outbound(topic, Outbound.route(topic, destination.runtime()), false, value, props));
    return (FutureValue<R>) future;
  }

  @Override
  public boolean routesLocalEvents() {
    return jmsEverywhere;
  }

  @Override
  public TransportStats stats() {
    return new TransportStats(sent.sum(), received.sum(), batches.sum(), rejected.sum());
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
    ValueFuture<Object> future = ValueFuture.remote(service, time, answers);
    long corr = pending.open(future, service);
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

  /** An event, a batch or a request for the runtime {@code runtime}. */
  private void onInbound(String runtime, Inbound inbound, Message m) {
    try {
      String kind = required(m, WireProperties.MSG);
      List<@Nullable Object> values = decode(m);
      switch (kind) {
        case WireProperties.MSG_EVENT, WireProperties.MSG_BATCH -> {
          for (Object v : values) {
            deliver(runtime, inbound, v);
          }
        }
        case WireProperties.MSG_REQUEST -> {
          String replyTo = required(m, WireProperties.NODE);
          long corr = requiredLong(m, WireProperties.CORR);
          if (values.size() != 1 || !(values.get(0) instanceof Request<?> r)) {
            throw new WireFormatException("a request message must hold one Request: " + values);
          }
          ask(runtime, inbound, r, replyTo, corr);
        }
        default ->
            throw new WireFormatException("unknown " + WireProperties.MSG + " '" + kind + "'");
      }
    } catch (WireFormatException | JMSException | RuntimeException e) {
      reject(m, e);
    }
  }

  private void deliver(String runtime, Inbound inbound, @Nullable Object v)
      throws WireFormatException {
    Event e = event(runtime, v);
    try {
      inbound.deliver(e.destination(), e);
      received.increment();
    } catch (ActiveException refused) {
      rejected.increment();
      LOG.warn("JMS transport {}: runtime {} refused {}: {}", node, runtime, e, refused.toString());
    }
  }

  private void ask(String runtime, Inbound inbound, Request<?> r, String replyTo, long corr)
      throws WireFormatException {
    Event e = event(runtime, r);
    received.increment();
    try {
      inbound.ask(e.destination(), r, (value, failure) -> answer(replyTo, corr, value, failure));
    } catch (ActiveException | UnsupportedOperationException refused) {
      answer(replyTo, corr, null, refused);
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
   * Sends the answer of a request (or look-up) back to the node that waits for it. Never throws: it
   * runs on the thread that completed the request, an object's worker among them; an answer that
   * cannot be sent is logged, and its future fails at its reply timeout.
   */
  private void answer(String node, long corr, @Nullable Object value, @Nullable Throwable failure) {
    if (closed.get()) {
      return;
    }
    try {
      enqueue(answerMessage(node, corr, value, failure));
    } catch (RuntimeException e) {
      LOG.warn(
          "JMS transport {}: the answer to request {} of {} is lost", this.node, corr, node, e);
    }
  }

  private Outbound answerMessage(
      String node, long corr, @Nullable Object value, @Nullable Throwable failure) {
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
    return new Outbound(Topic.FUTURE, null, false, body, props);
  }

  /** An answer to one of this transport's requests or look-ups. */
  private void onAnswer(Message m) {
    try {
      String kind = required(m, WireProperties.MSG);
      long corr = requiredLong(m, WireProperties.CORR);
      List<@Nullable Object> values = decode(m);
      if (values.size() != 1) {
        throw new WireFormatException("an answer must hold one value, not " + values.size());
      }
      ValueFuture<Object> f = pending.take(corr);
      if (f == null) {
        LOG.debug("JMS transport {}: late or duplicate answer {}", node, corr);
        return;
      }
      received.increment();
      switch (kind) {
        case WireProperties.MSG_ANSWER -> f.complete(values.get(0));
        case WireProperties.MSG_FAILURE ->
            f.fail(new ActiveException("failed remotely: " + required(m, WireProperties.ERROR)));
        default -> throw new WireFormatException("unknown answer kind '" + kind + "'");
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
        answer(from, corr, a, null);
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

  private static long requiredLong(Message m, String property)
      throws JMSException, WireFormatException {
    if (!(m.getObjectProperty(property) instanceof Long v)) {
      throw new WireFormatException("property " + property + " missing or not a long");
    }
    return v;
  }

  /** Counts and logs a dead letter: every one up to a few, then one in a thousand. */
  private void reject(@Nullable Message m, Exception why) {
    rejected.increment();
    long n = rejected.sum();
    if (n <= LOGGED_REJECTIONS || n % 1_000 == 0) {
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
      sending.submit(Outbound.STOP);
      sender.join(10_000);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    sweeper.shutdownNow();
    for (JmsSubscription s : List.copyOf(subscriptions)) {
      s.close();
    }
    pending.abandonAll(new ActiveException("JMS transport " + node + " closed before the answer"));
    answers.close();
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
