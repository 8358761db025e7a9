package org.armgals.active;

import org.jspecify.annotations.Nullable;

/** The receiving side's handle on a sender's future. */
interface Reply<R extends @Nullable Object> {
  /** The request succeeded with {@code value}. */
  void complete(R value);

  /** The request failed, or will never run. */
  void fail(Throwable cause);
}
