package org.armgals.active.spi;

/**
 * Hears the runtimes that a transport links join, leave and fall silent (the JMS transport's {@code
 * Presence} tells it; the kernel listens to mark the models of a lost runtime's entities lost).
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
