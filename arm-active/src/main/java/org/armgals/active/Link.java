package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import org.jspecify.annotations.Nullable;

/**
 * A node of an object's buffer: an {@link Envelope}, or the object itself, which is its buffer's
 * first node while the buffer is empty (so an idle object keeps no envelope alive). {@link #next}
 * is written by producers (release) and read by the consumer (acquire).
 */
abstract class Link {
  private static final VarHandle NEXT;

  static {
    try {
      NEXT = MethodHandles.lookup().findVarHandle(Link.class, "next", Link.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  @SuppressWarnings("unused") // accessed through NEXT
  private volatile @Nullable Link next;

  final @Nullable Link next() {
    return (Link) NEXT.getAcquire(this);
  }

  final void setNext(@Nullable Link n) {
    NEXT.setRelease(this, n);
  }
}
