package org.armgals.active.jms;

import jakarta.jms.JMSException;

/**
 * A presence stepped by hand, as PresenceTest steps one: it beats and judges silences only when
 * {@link #step} is called, so a test decides when a runtime falls silent.
 */
public final class SteppedPresence implements AutoCloseable {
  private final PresenceImpl presence;

  private SteppedPresence(PresenceImpl presence) {
    this.presence = presence;
  }

  /** Starts {@code builder}'s presence without its own thread. */
  public static SteppedPresence start(Presence.Builder builder) {
    return new SteppedPresence(PresenceImpl.start(builder.validate(), false));
  }

  /** One beat, and one judgment of the others' silences. */
  public void step() throws JMSException {
    presence.doWork();
  }

  @Override
  public void close() {
    presence.close();
  }
}
