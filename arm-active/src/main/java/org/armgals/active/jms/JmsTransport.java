package org.armgals.active.jms;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.active.ActiveException;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.BufferFullException;
import org.armgals.active.Event;
import org.armgals.active.Filter;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.FutureValue;
import org.armgals.active.ObjectConfig;
import org.armgals.active.OverflowPolicy;
import org.armgals.active.Request;
import org.armgals.active.Selectable;
import org.armgals.active.TimeSource;
import org.armgals.active.TransportStats;
import org.armgals.active.spi.AllowList;
import org.armgals.active.spi.NameService;
import org.armgals.active.spi.Transport;
import org.jspecify.annotations.Nullable;

/**
 * The {@link Transport} between runtimes over Jakarta Messaging 3.1 and Apache ActiveMQ Artemis
 * (paper §2.3, §4.1; docs/architecture.md, runtime semantics 5-7). Give one to {@link
 * ActiveRuntime.Builder#transport}; several runtimes may share one.
 *
 * <p>Events to another runtime travel as JMS messages on the paper's topics under a prefix ({@link
 * Topic}), encoded by an explicit codec over the allow-list given to the builder: no Java
 * serialization. The answer to a {@link Request} comes back on {@code active/Future} and completes
 * the asker's future. When events to one runtime back up, up to {@link Builder#maxBatch} travel in
 * one message. A message that fails to decode, names a type not allowed, is oversized or lacks its
 * properties is logged, counted in {@link TransportStats#rejected()} and dropped.
 *
 * <p>Delivery ({@link Guarantee}, chosen per topic and per type): at most once by default, the
 * fastest; at least once with duplicates suppressed where the builder says so. On every route (what
 * one transport sends to one runtime on one topic with one guarantee) messages carry sequence
 * numbers, keep their order, and what never arrives is counted in {@link TransportStats#lost()} and
 * told to the receiving runtime's {@link org.armgals.active.spi.ErrorHandler#onLost} when the next
 * message of the route arrives. Every message that reaches a transport is counted once, in one of
 * {@link TransportStats}'s inbound figures.
 *
 * <p>Threading: every method may be called from any thread, and none waits for the broker: an event
 * is encoded on the caller's thread (so a type not allowed fails there) and queued to the
 * transport's sender threads; a full queue applies {@link Builder#outboundQueue}'s policy. A
 * refusal at the receiving runtime (stopped object, full buffer) is counted there, not thrown to
 * the sender.
 */
public interface JmsTransport extends Transport, NameService {

  /** The paper's topics; each is named {@code <prefix>/<path>} on the broker. */
  enum Topic {
    /** Events and requests between entities (the default for every event type). */
    ENTITY("arm/Entity"),
    /** Events to structural meta-entities. */
    SMETA("arm/SMeta"),
    /** Events to behavioral meta-entities. */
    BMETA("arm/BMeta"),
    /** Answers to requests, and to name look-ups. */
    FUTURE("active/Future"),
    /** Name look-ups (not a topic of the paper). */
    NAMES("arm/Names");

    private final String path;

    Topic(String path) {
      this.path = path;
    }

    /** The topic's name under the prefix. */
    public String path() {
      return path;
    }
  }

  /**
   * How the messages of a type or a topic travel (see {@link Builder#guarantee(Topic, Guarantee)}).
   * Either way a route keeps its order and counts what it loses; two routes of different guarantees
   * to the same runtime are not ordered with each other.
   */
  enum Guarantee {
    /**
     * Non-persistent messages, sent once, to subscriptions that live as long as their runtime: a
     * broker restart or a send the broker refuses loses them, and the receiver counts the loss. The
     * default, and the fastest.
     */
    AT_MOST_ONCE,
    /**
     * Persistent messages, each with Artemis's duplicate-detection id, sent again until the broker
     * has confirmed them, to a shared durable subscription per receiving runtime and topic that
     * outlives its consumer; a message delivered twice is dropped by the receiver and counted in
     * {@link TransportStats#duplicates()}. Nothing is lost across a broker restart when the broker
     * keeps a journal (a standalone broker with persistence on): 0 lost, 0 delivered twice. The
     * receiver acknowledges a message once it is in the destination object's buffer.
     */
    AT_LEAST_ONCE
  }

  /** A builder with the defaults: an embedded broker, prefix {@code armgals}. */
  static Builder builder() {
    return new Builder();
  }

  /** The broker's name for {@code topic}: {@code <prefix>/<path>}. */
  String topicName(Topic topic);

  /** The URL the transport connected to. */
  String brokerUrl();

  /** The embedded broker this transport started and owns, with its netty URL and login, if any. */
  java.util.Optional<EmbeddedBroker> embeddedBroker();

  /**
   * Registers {@code address} under {@code name} in the name service: {@link #lookup} on any
   * transport on the same broker (and prefix) finds it while this transport is open.
   *
   * @throws IllegalArgumentException {@code name} is blank
   */
  @Override
  void register(String name, Address address);

  /**
   * Fails at once, with an {@link ActiveException} naming {@code runtime} and {@code why}, every
   * request this transport sent to an object of {@code runtime} whose answer has not come: that
   * runtime was declared lost (a killed JVM) or left. Requests sent later wait for their answer as
   * usual. {@link Presence.Builder#failRequestsOf} calls it for every runtime its presence declares
   * lost or gone.
   *
   * @return how many requests failed
   */
  int failRequestsTo(String runtime, String why);

  /** Removes a registration of this transport. Idempotent. */
  @Override
  void unregister(String name);

  /**
   * The address registered under {@code name}: at once if this transport holds it, otherwise asked
   * over the broker. The future fails with {@link FutureTimeoutException} at the reply timeout if
   * no transport answers (an unknown name).
   */
  @Override
  FutureValue<Address> lookup(String name);

  /**
   * Publishes {@code event} on {@code topic} to every {@link Subscription} whose filter takes it:
   * those of this transport in memory (no encoding; the filter is evaluated on the event's
   * properties), those of other transports through the broker (the filter is the subscription's JMS
   * selector there). The event's type must be on the allow-list.
   *
   * @throws IllegalArgumentException {@code topic} is FUTURE or NAMES, or the type is not allowed
   */
  void publish(Topic topic, Event event);

  /**
   * Subscribes {@code handler} to the events published on {@code topic} that {@code filter} takes
   * (its properties: {@code kind}, {@code sender}, {@code destination}, {@code seq} and those of a
   * {@link Selectable} event).
   *
   * @throws IllegalArgumentException {@code topic} is FUTURE or NAMES
   */
  Subscription subscribe(
      Topic topic, Filter filter, java.util.function.Consumer<? super Event> handler);

  @Override
  TransportStats stats();

  /** Closes the connection and, if it started one, the embedded broker. Idempotent. */
  @Override
  void close();

  /** Settings of a JMS transport; validated by {@link #build()}. Not thread-safe. */
  final class Builder implements AllowList {
    @Nullable String url;
    @Nullable String user;
    @Nullable String password;
    int nettyPort;
    final Map<String, String> options = new LinkedHashMap<>();
    String prefix = "armgals";
    final List<Class<?>> allowed = new ArrayList<>();
    final Map<Class<?>, Topic> topics = new LinkedHashMap<>();
    boolean jmsEverywhere;
    int maxBatch = 64;
    int maxMessageBytes = 1 << 20;
    Duration replyTimeout = Duration.ofSeconds(30);
    TimeSource timeSource = TimeSource.system();
    final Map<Topic, Guarantee> topicGuarantees = new LinkedHashMap<>();
    final Map<Class<?>, Guarantee> typeGuarantees = new LinkedHashMap<>();
    int outboundCapacity = 16_384;
    OverflowPolicy outboundPolicy = OverflowPolicy.block(ObjectConfig.DEFAULT_BLOCK_TIMEOUT);

    Builder() {}

    /** Starts and owns an in-VM broker (the default). */
    public Builder embeddedBroker() {
      this.url = null;
      this.nettyPort = 0;
      return this;
    }

    /**
     * Starts and owns an embedded broker that other JVMs of this host reach on {@code
     * tcp://127.0.0.1:<port>} with the login it generates for this run ({@link #embeddedBroker()}
     * tells it to whoever starts those JVMs).
     */
    public Builder embeddedBroker(int port) {
      if (port < 1 || port > 65_535) {
        throw new IllegalArgumentException("port must be in [1, 65535], was " + port);
      }
      this.url = null;
      this.nettyPort = port;
      return this;
    }

    /**
     * Connects to a broker by URL ({@code tcp://host:61616}, {@code vm://0}, {@link
     * EmbeddedBroker#inVmUrl()}) without credentials: an in-VM broker of this JVM, or a broker
     * whose acceptor takes anyone (none that armgals starts).
     */
    public Builder broker(String url) {
      requireNonNull(url, "url");
      if (!url.matches("(tcp|vm|ssl|(udp)|(jgroups))://.+")) {
        throw new IllegalArgumentException(
            "url must look like tcp://host:port or vm://n, was '" + url + "'");
      }
      this.url = url;
      this.user = null;
      this.password = null;
      return this;
    }

    /** Connects to a broker by URL with credentials. */
    public Builder broker(String url, String user, String password) {
      broker(url);
      this.user = requireNonNull(user, "user");
      this.password = requireNonNull(password, "password");
      return this;
    }

    /**
     * An Artemis connection option added to the URL's query, passed through as is: TLS ({@code
     * sslEnabled=true}, {@code trustStorePath}, {@code trustStorePassword}, {@code
     * keyStorePath}...), reconnection ({@code reconnectAttempts}, {@code retryInterval}) and the
     * rest of Artemis's URL parameters. The transport adds {@code reconnectAttempts=-1} unless
     * given.
     */
    public Builder brokerOption(String key, String value) {
      requireNonNull(key, "key");
      requireNonNull(value, "value");
      if (!key.matches("[A-Za-z][A-Za-z0-9.]*")) {
        throw new IllegalArgumentException("not an Artemis URL parameter name: '" + key + "'");
      }
      options.put(key, value);
      return this;
    }

    /** The prefix of the topics, so that applications can share a broker; default armgals. */
    public Builder prefix(String prefix) {
      requireNonNull(prefix, "prefix");
      if (!prefix.matches("[A-Za-z0-9_\\-]+(/[A-Za-z0-9_\\-]+)*")) {
        throw new IllegalArgumentException(
            "prefix must be letters, digits, '_' or '-' in '/'-separated parts, was '"
                + prefix
                + "'");
      }
      this.prefix = prefix;
      return this;
    }

    /**
     * Adds records and enums to the allow-list of the wire codec: events, requests, answers and the
     * values they hold. Everything else is refused, on both sides.
     */
    @Override
    public Builder allow(Class<?>... types) {
      for (Class<?> t : types) {
        allowed.add(requireNonNull(t, "type"));
      }
      return this;
    }

    /**
     * {@link #allow(Topic, Class)} with the topic named by its {@linkplain Topic#path() path}:
     * {@code arm/Entity}, {@code arm/SMeta} or {@code arm/BMeta}.
     *
     * @throws IllegalArgumentException no such topic, or one of FUTURE and NAMES
     */
    @Override
    public Builder allow(String topic, Class<? extends Event> type) {
      requireNonNull(topic, "topic");
      for (Topic t : List.of(Topic.ENTITY, Topic.SMETA, Topic.BMETA)) {
        if (t.path().equals(topic)) {
          return allow(t, type);
        }
      }
      throw new IllegalArgumentException(
          "no topic '" + topic + "'; expected arm/Entity, arm/SMeta or arm/BMeta");
    }

    /** {@link #guarantee(Guarantee, Class[])} at least once. */
    @Override
    public Builder atLeastOnce(Class<?>... types) {
      return guarantee(Guarantee.AT_LEAST_ONCE, types);
    }

    /** Allows an event type that travels on {@code topic} rather than {@link Topic#ENTITY}. */
    public Builder allow(Topic topic, Class<? extends Event> type) {
      requireNonNull(topic, "topic");
      requireNonNull(type, "type");
      if (topic == Topic.FUTURE || topic == Topic.NAMES) {
        throw new IllegalArgumentException(
            "events travel on ENTITY, SMETA or BMETA, not " + topic + " (" + type.getName() + ")");
      }
      allowed.add(type);
      topics.put(type, topic);
      return this;
    }

    /**
     * "JMS everywhere": events between objects of one runtime go through the broker too, through
     * references from {@link ActiveRuntime#ref}. The paper's behavior, and the baseline of the
     * benchmarks. Default false.
     */
    public Builder jmsEverywhere(boolean on) {
      this.jmsEverywhere = on;
      return this;
    }

    /** The most events one message carries when events to one runtime back up; 1: no batching. */
    public Builder maxBatch(int maxBatch) {
      if (maxBatch < 1 || maxBatch > 4096) {
        throw new IllegalArgumentException("maxBatch must be in [1, 4096], was " + maxBatch);
      }
      this.maxBatch = maxBatch;
      return this;
    }

    /** The largest message body accepted; larger inbound ones are rejected. Default 1 MiB. */
    public Builder maxMessageBytes(int bytes) {
      if (bytes < 1024 || bytes > 64 << 20) {
        throw new IllegalArgumentException(
            "maxMessageBytes must be in [1024, 67108864], was " + bytes);
      }
      this.maxMessageBytes = bytes;
      return this;
    }

    /**
     * How long a request or look-up waits for its answer before its future fails with {@link
     * FutureTimeoutException} (an answer lost with a broker restart ends so). Default 30 s.
     */
    public Builder replyTimeout(Duration timeout) {
      requireNonNull(timeout, "timeout");
      if (timeout.isNegative() || timeout.isZero()) {
        throw new IllegalArgumentException("replyTimeout must be > 0, was " + timeout);
      }
      this.replyTimeout = timeout;
      return this;
    }

    /**
     * The guarantee of every event and request type that travels on {@code topic} (ENTITY, SMETA or
     * BMETA), unless {@link #guarantee(Guarantee, Class[])} says otherwise for its type. Default
     * {@link Guarantee#AT_MOST_ONCE}.
     *
     * @throws IllegalArgumentException {@code topic} is FUTURE or NAMES (an answer travels as its
     *     request does; look-ups at most once)
     */
    public Builder guarantee(Topic topic, Guarantee guarantee) {
      requireNonNull(topic, "topic");
      requireNonNull(guarantee, "guarantee");
      if (topic == Topic.FUTURE || topic == Topic.NAMES) {
        throw new IllegalArgumentException(
            "a guarantee is chosen for ENTITY, SMETA or BMETA, not " + topic);
      }
      topicGuarantees.put(topic, guarantee);
      return this;
    }

    /**
     * The guarantee of the event and request types {@code types} (each must be on the allow-list by
     * {@link #build()}), whatever their topic's; a request's answer travels with the request's
     * guarantee. Published events travel at most once.
     */
    public Builder guarantee(Guarantee guarantee, Class<?>... types) {
      requireNonNull(guarantee, "guarantee");
      for (Class<?> t : types) {
        requireNonNull(t, "type");
        if (!Event.class.isAssignableFrom(t)) {
          throw new IllegalArgumentException(
              "a guarantee is chosen for event and request types, not " + t.getName());
        }
        typeGuarantees.put(t, guarantee);
      }
      return this;
    }

    /**
     * The bound of the outbound queue, where sends wait for the broker, and what a send finds when
     * it is full: the policies of an object's buffer ({@link OverflowPolicy}), applied on the
     * caller's thread. {@link OverflowPolicy#block} waits for room only while the connection is up
     * (a sender faster than the broker is paced by it) and refuses at once with {@link
     * BufferFullException} while it is down: no call waits for a broker that is away. A dropped
     * event or answer is counted in {@link TransportStats#unsent()}; a dropped request fails its
     * future at once; an at-least-once message is never dropped (a drop policy refuses it). Default
     * 16,384 messages and {@code block(}{@link ObjectConfig#DEFAULT_BLOCK_TIMEOUT}{@code )}, as an
     * asynchronous object's buffer.
     */
    public Builder outboundQueue(int capacity, OverflowPolicy policy) {
      requireNonNull(policy, "policy");
      if (capacity < 16 || capacity > 1 << 24) {
        throw new IllegalArgumentException(
            "outbound queue capacity must be in [16, 16777216], was " + capacity);
      }
      this.outboundCapacity = capacity;
      this.outboundPolicy = policy;
      return this;
    }

    /** Where the reply timeout reads time; default {@link TimeSource#system()}. */
    public Builder timeSource(TimeSource timeSource) {
      this.timeSource = requireNonNull(timeSource, "timeSource");
      return this;
    }

    /**
     * A connected transport.
     *
     * @throws IllegalArgumentException a type of the allow-list cannot be encoded, or a type given
     *     a guarantee is not on it (the message names it)
     * @throws IllegalStateException the broker could not be started or reached, or refused the
     *     login (the message says which); the cause says why
     */
    public JmsTransport build() {
      for (Class<?> t : typeGuarantees.keySet()) {
        if (!allowed.contains(t)) {
          throw new IllegalArgumentException(
              t.getName() + " was given a guarantee but is not on the allow-list; allow it too");
        }
      }
      return JmsTransportImpl.connect(this);
    }
  }
}
