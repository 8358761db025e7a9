package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import org.jspecify.annotations.Nullable;

/**
 * A thread that runs activations: which object's activation it is in, and the places that
 * activation has taken from its buffer and not yet given back to the senders.
 *
 * <p>A worker is its own carrier, installed in one thread-local once, when its thread starts: an
 * activation then only writes two fields of it, with no thread-local write per activation. A thread
 * that runs an activation by hand (a dispatcher driven by hand, a shutdown discarding what is still
 * queued) gets a carrier on its first activation.
 *
 * <p>Workers are virtual threads. A platform thread is in an activation only while {@link
 * #PLATFORM_ACTIVATIONS} counts it, so a platform thread that sends (a program's main thread, a
 * transport's listener) learns that it runs no activation from one read of a counter that is seldom
 * written, without a thread-local lookup per send.
 */
class Carrier {
  private static final ThreadLocal<@Nullable Carrier> CURRENT = new ThreadLocal<>();

  /**
   * Ints before and after the element {@link #PLATFORM_ACTIVATIONS} counts in: a line each side.
   */
  private static final int PAD = 16;

  /**
   * Activations run by hand on platform threads right now, in the whole JVM: the element {@link
   * #PAD}, which the others keep alone on its cache line (decision 0082). Every send from a
   * platform thread reads it. As an {@code AtomicInteger} it was made with the first worker, just
   * before it, and shared a line with that worker's fields, written on every activation: each send
   * from a program's main thread then waited for that line to come from the worker's core.
   */
  private static final int[] PLATFORM_ACTIVATIONS = new int[2 * PAD + 1];

  private static final VarHandle COUNT = MethodHandles.arrayElementVarHandle(int[].class);

  /** The object whose activation this thread is running, or null. */
  @Nullable Core<?> running;

  /** Events the running activation took from its object's buffer, not yet given back. */
  int taken;

  /** How many taken events the running activation gives back at once; see {@code Core#taken}. */
  int takenBatch;

  /**
   * The running activation's place in its object's buffer, while it takes events: its object's
   * {@code head}, held here so that taking an event writes nothing in the object (written back when
   * the activation ends). Null when the activation takes no events from a linked buffer.
   */
  @Nullable Link cursor;

  /** The calling thread's carrier, or null if it is running no activation. */
  static @Nullable Carrier current() {
    if (!Thread.currentThread().isVirtual()
        && (int) COUNT.getVolatile(PLATFORM_ACTIVATIONS, PAD) == 0) {
      return null;
    }
    return CURRENT.get();
  }

  /** The object whose activation the calling thread is running, or null. */
  static @Nullable Core<?> running() {
    Carrier c = current();
    return c == null ? null : c.running;
  }

  /** Makes {@code carrier} the calling thread's, for good: a worker, when its thread starts. */
  static void install(Carrier carrier) {
    CURRENT.set(carrier);
  }

  /**
   * Runs one activation of {@code core} on the calling thread, which is not a worker of its runtime
   * (a dispatcher driven by hand, or a shutdown).
   */
  static void runByHand(Core<?> core) {
    Carrier c = CURRENT.get();
    if (c == null) {
      c = new Carrier();
      CURRENT.set(c);
    }
    boolean platform = !Thread.currentThread().isVirtual();
    if (platform) {
      COUNT.getAndAdd(PLATFORM_ACTIVATIONS, PAD, 1);
    }
    try {
      core.run(c);
    } finally {
      if (platform) {
        COUNT.getAndAdd(PLATFORM_ACTIVATIONS, PAD, -1);
      }
    }
  }
}
