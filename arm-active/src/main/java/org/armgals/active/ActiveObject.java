package org.armgals.active;

/**
 * A live active object, as handed to whoever created it: a reference ({@link ActiveRef}) plus what
 * only the owner should do — look at its buffer and stop it.
 *
 * <p>An active object processes the events of its bounded buffer one at a time (paper §4.1): in the
 * {@link Mode#ASYNCHRONOUS asynchronous} mode as they come, skipping those that are not processable
 * and retrying them after its state changes, dormant with no thread when nothing is processable; in
 * the {@link Mode#SYNCHRONOUS synchronous} mode once per release of its clock. A failure while
 * processing never stops it.
 *
 * @param <S> the type of its servant
 */
public interface ActiveObject<S> extends ActiveRef<S> {

  /** Its mode, fixed at creation. */
  Mode mode();

  /** The configuration it was made with. */
  ObjectConfig config();

  /**
   * How many events wait in its buffer (processable or not). Exact while the object is idle; while
   * it runs, events it has already taken in the current activation may still be counted, at most
   * 1/64 of the capacity (none for buffers under 128). The capacity check uses the same count.
   */
  int queueDepth();

  /** Whether it has been stopped. */
  boolean isStopped();

  /**
   * Stops it: it takes no more events; the events still queued are discarded and the futures of
   * their requests fail with {@link ObjectStoppedException}; an event being processed finishes.
   * Idempotent; any thread.
   */
  void stop();
}
