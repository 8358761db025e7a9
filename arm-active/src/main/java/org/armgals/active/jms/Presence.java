package org.armgals.active.jms;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.PresenceEvent;
import org.armgals.active.spi.PresenceListener;
import org.jspecify.annotations.Nullable;

/**
 * The presence of one runtime on a broker: it publishes a beat every {@link Builder#period} on the
 * topic {@code <prefix>/arm/Presence}, hears the beats of the other runtimes of the same prefix,
 * and tells its listeners when one joins, leaves (closes its presence) or is lost (no beat for
 * {@link Builder#missedBeats} periods: a killed JVM, a hung one, a cut link).
 *
 * <p>While its own connection to the broker is down, a presence declares nobody lost (it cannot
 * tell), and once reconnected it gives every runtime it knew a fresh allowance.
 *
 * <p>Threading: every method may be called from any thread; listeners are called one event at a
 * time on the presence's threads.
 */
public interface Presence extends AutoCloseable {

  /** A builder; {@link Builder#broker} and {@link Builder#runtime} are required. */
  static Builder builder() {
    return new Builder();
  }

  /** This runtime's name, as others see it. */
  String runtime();

  /** The other runtimes present now: heard, and neither left nor lost since. */
  Set<String> peers();

  /** Events listeners threw on, since the start. */
  long listenerFailures();

  /** Says this runtime is leaving, then closes the connection. Idempotent. */
  @Override
  void close();

  /** Settings of a presence; validated by {@link #build()}. Not thread-safe. */
  final class Builder {
    @Nullable String url;
    @Nullable String user;
    @Nullable String password;
    String prefix = "armgals";
    @Nullable String runtime;
    Duration period = Duration.ofMillis(250);
    int missedBeats = 4;
    TimeSource timeSource = TimeSource.system();
    final List<PresenceListener> listeners = new ArrayList<>();

    Builder() {}

    /**
     * The broker, without credentials: an embedded broker's in-VM acceptor (its network acceptor
     * requires its login, as any broker reached beyond this JVM should).
     */
    public Builder broker(String url) {
      this.url = requireNonNull(url, "url");
      this.user = null;
      this.password = null;
      return this;
    }

    /** The broker, with credentials (a broker reached beyond loopback must require them). */
    public Builder broker(String url, String user, String password) {
      this.url = requireNonNull(url, "url");
      this.user = requireNonNull(user, "user");
      this.password = requireNonNull(password, "password");
      return this;
    }

    /** The prefix of the topic; the same as the runtimes' transport. Default armgals. */
    public Builder prefix(String prefix) {
      this.prefix = requireNonNull(prefix, "prefix");
      return this;
    }

    /** This runtime's name: the one its references carry. */
    public Builder runtime(String runtime) {
      this.runtime = requireNonNull(runtime, "runtime");
      return this;
    }

    /** How often this runtime beats; default 250 ms. */
    public Builder period(Duration period) {
      this.period = requireNonNull(period, "period");
      return this;
    }

    /** How many periods without a beat make a runtime lost; default 4, at least 2. */
    public Builder missedBeats(int missedBeats) {
      this.missedBeats = missedBeats;
      return this;
    }

    /** Where silences are measured; default {@link TimeSource#system()}. */
    public Builder timeSource(TimeSource timeSource) {
      this.timeSource = requireNonNull(timeSource, "timeSource");
      return this;
    }

    /**
     * Makes the in-flight requests of {@code transport} to a runtime fail as soon as this presence
     * declares that runtime lost or gone ({@link JmsTransport#failRequestsTo}), rather than at
     * their reply timeout.
     */
    public Builder failRequestsOf(JmsTransport transport) {
      requireNonNull(transport, "transport");
      return listener(
          event -> {
            switch (event) {
              case PresenceEvent.Lost lost ->
                  transport.failRequestsTo(
                      lost.runtime(), "was declared lost (silent for " + lost.silence() + ")");
              case PresenceEvent.Left left -> transport.failRequestsTo(left.runtime(), "left");
              case PresenceEvent.Joined joined -> {}
            }
          });
    }

    /** Adds a listener. */
    public Builder listener(PresenceListener listener) {
      listeners.add(requireNonNull(listener, "listener"));
      return this;
    }

    /**
     * A presence, connected and beating.
     *
     * @throws IllegalArgumentException a setting is out of range (the message names it)
     * @throws IllegalStateException the broker could not be reached; the cause says why
     */
    public Presence build() {
      return PresenceImpl.start(validate(), true);
    }

    Builder validate() {
      if (url == null || url.isBlank()) {
        throw new IllegalArgumentException("broker url must be set, was " + url);
      }
      if (runtime == null || runtime.isBlank()) {
        throw new IllegalArgumentException(
            "runtime must be a non-blank name, was '" + runtime + "'");
      }
      if (!prefix.matches("[A-Za-z0-9_\\-]+(/[A-Za-z0-9_\\-]+)*")) {
        throw new IllegalArgumentException(
            "prefix must be letters, digits, '_' or '-' in '/'-separated parts, was '"
                + prefix
                + "'");
      }
      if (period.compareTo(Duration.ofMillis(10)) < 0
          || period.compareTo(Duration.ofMinutes(1)) > 0) {
        throw new IllegalArgumentException("period must be in [10 ms, 1 min], was " + period);
      }
      if (missedBeats < 2 || missedBeats > 1000) {
        throw new IllegalArgumentException("missedBeats must be in [2, 1000], was " + missedBeats);
      }
      return this;
    }
  }
}
