package org.armgals.active.jms;

import org.armgals.active.Filter;

/**
 * A subscription to the events published on one of a {@link JmsTransport}'s topics, through a
 * {@link Filter} (paper §2.3: a meta-entity connects to and detaches from its base entities by
 * content). Made by {@link JmsTransport#subscribe}.
 *
 * <p>Its filter can be {@linkplain #swap swapped} at run time without losing or duplicating an
 * event: an event published before the swap began is judged by the old filter, one published after
 * it ended by the new one, and one published during the swap is delivered once if either filter
 * takes it.
 *
 * <p>Threading: the handler is called one event at a time, never concurrently with itself.
 */
public interface Subscription extends AutoCloseable {

  /** The filter in force. */
  Filter filter();

  /**
   * Replaces the filter; returns once the new one is in force on the broker too.
   *
   * @throws IllegalStateException the subscription is closed, or the broker did not confirm the
   *     swap within 10 seconds (the new filter is then in force with the union of both)
   */
  void swap(Filter next);

  /** Stops the subscription. Idempotent. */
  @Override
  void close();
}
