package org.armgals.active;

import java.util.Optional;

/** What code running inside an active object can ask about the object running it. */
public final class ActiveContext {
  private ActiveContext() {}

  /**
   * The object whose event or cycle the calling thread is processing.
   *
   * @return empty outside any active object
   */
  public static Optional<ActiveObject<?>> current() {
    return Optional.ofNullable(Core.current());
  }

  /**
   * A reference to the object whose event the calling thread is processing, typed as the caller
   * says.
   *
   * @throws IllegalStateException called outside an active object
   */
  @SuppressWarnings("unchecked")
  public static <S> ActiveRef<S> self() {
    Core<?> core = Core.current();
    if (core == null) {
      throw new IllegalStateException("ActiveContext.self() called outside an active object");
    }
    return (ActiveRef<S>) core;
  }
}
