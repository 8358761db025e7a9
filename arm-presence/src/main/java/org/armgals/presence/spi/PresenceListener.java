package org.armgals.presence.spi;

import org.armgals.presence.PresenceEvent;

/**
 * Hears the runtimes of a broker join, leave and fall silent.
 *
 * <p>Threading: called on the presence's own threads, one event at a time (never concurrently with
 * itself), in the order the presence saw the changes. It should return quickly; an exception it
 * throws is logged and counted, and the other listeners still hear the event.
 */
@FunctionalInterface
public interface PresenceListener {

  /** One change in the set of runtimes present. */
  void onPresence(PresenceEvent event);
}
