package org.armgals.bench.savina;

/**
 * The trivial servant (or actor state) of an idle object: one counter, touched once so that the
 * object has processed a message before it is measured. Its own size is not charged to the runtime.
 *
 * <p>Threading: touched by the object that owns it only; read by the harness after the object's
 * reply has been seen.
 */
public final class Idle {
  private int touches;

  /** Counts one message. */
  public void touch() {
    touches++;
  }

  /** How many messages it has seen. */
  public int touches() {
    return touches;
  }
}
