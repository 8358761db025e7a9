package org.armgals.active;

/** How {@link ActiveRuntime#shutdown} ends the runtime's objects. */
public enum ShutdownMode {
  /**
   * Let the objects process what they have queued, including what they send each other while
   * draining, until no object has a processable event (events whose guard never opens do not keep
   * the runtime alive); then stop them all. What is left when the timeout expires is cancelled.
   */
  DRAIN,
  /**
   * Stop every object now: queued events are discarded, their futures fail with {@link
   * ObjectStoppedException}, events being processed finish, and threads waiting by necessity inside
   * objects are interrupted.
   */
  CANCEL
}
