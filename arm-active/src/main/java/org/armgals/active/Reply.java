package org.armgals.active;

import org.jspecify.annotations.Nullable;

/** The receiving side's handle on a sender's future. */
interface Reply<R extends @Nullable Object> {
  /** The request succeeded with {@code value}. */
  void complete(R value);

  /** The request failed in the receiver: its servant (or its guard) threw {@code cause}. */
  void fail(Throwable cause);

  /** The request will never run (dropped, or the receiver stopped) for {@code cause}. */
  void abandon(ActiveException cause);
}
