package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.jspecify.annotations.Nullable;

/**
 * The live objects of a runtime, indexed by object number: chunks of {@link #CHUNK} slots, so an
 * object costs one reference here (a hash map entry and its boxed key would cost about 56 bytes,
 * more than half of an idle object's budget). A chunk is freed once every number in it has been
 * handed out and every object numbered in it has been removed.
 *
 * <p>Numbering, insertion, removal and lookups are lock-free: a number is one atomic increment, a
 * slot is set and cleared by release stores (each object is removed once at most), and each chunk
 * counts its removals; the count of live objects is computed from those, not kept. Only making a
 * chunk, growing the array of chunks and freeing a chunk take a lock, once per {@link #CHUNK}
 * objects (an object created and stopped per message, as in a creation workload, made the lock per
 * object contended: the creator and the stopping objects run on different workers).
 */
final class ObjectTable {
  static final int CHUNK = 1024;
  private static final VarHandle SLOT = MethodHandles.arrayElementVarHandle(Core[].class);
  private static final VarHandle GONE;

  static {
    try {
      GONE = MethodHandles.lookup().findVarHandle(Chunk.class, "gone", int.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  /** A chunk's slots, read on every addition and removal. */
  private abstract static class Slots {
    final @Nullable Core<?>[] slots = new Core<?>[CHUNK];

    // Keeps the removals' counter (a subclass's field, laid out after these) off the line of the
    // slots' reference: the creator reads that on every addition while objects that stop, on
    // other workers, count their removals. One chunk holds 1024 objects, so this costs nothing.
    @SuppressWarnings("unused")
    private long p1, p2, p3, p4, p5, p6, p7;
  }

  /** {@link #CHUNK} slots and how many of their objects have been removed. */
  private static final class Chunk extends Slots {
    @SuppressWarnings("unused") // accessed through GONE
    volatile int gone;
  }

  private final ReentrantLock lock = new ReentrantLock();
  private volatile @Nullable Chunk[] chunks = new Chunk[0];
  private final AtomicLong lastId = new AtomicLong();

  /** Chunks freed so far, each once all of its numbers were gone; written under the lock. */
  private long freedChunks;

  /** Numbers a new object and stores the one {@code make} builds with that number. */
  <S> Core<S> add(java.util.function.LongFunction<Core<S>> make) {
    long id = lastId.incrementAndGet();
    Core<S> core;
    try {
      core = make.apply(id);
    } catch (RuntimeException | Error e) {
      gone(id); // the number is used up: its chunk must still be freed one day
      throw e;
    }
    SLOT.setRelease(chunkFor(id).slots, slotOf(id), core);
    return core;
  }

  /**
   * Removes {@code core} if it is there. An object is removed once at most (by the one call of its
   * {@code stop()} that sets its stopped bit), and its slot never holds another object: a check and
   * a release store do, with no compare-and-set.
   */
  void remove(Core<?> core) {
    Chunk chunk = chunk(chunkOf(core.id));
    int slot = slotOf(core.id);
    if (chunk == null || SLOT.getAcquire(chunk.slots, slot) != core) {
      return;
    }
    SLOT.setRelease(chunk.slots, slot, (Core<?>) null);
    gone(core.id);
  }

  /**
   * Counts the number {@code id} as gone; its chunk is freed with its last one. Every number of a
   * chunk is handed out before its last one is gone, since an object is removed only after it was
   * stored, so no insertion can come after the freeing.
   */
  private void gone(long id) {
    int c = chunkOf(id);
    Chunk chunk = chunkFor(id);
    if ((int) GONE.getAndAdd(chunk, 1) + 1 == CHUNK) {
      lock.lock();
      try {
        @Nullable Chunk[] cs = chunks;
        if (cs[c] == chunk) {
          cs[c] = null;
          chunks = cs; // publish
          freedChunks++;
        }
      } finally {
        lock.unlock();
      }
    }
  }

  /** The live object numbered {@code id}, or null. */
  @Nullable Core<?> get(long id) {
    if (id < 1) {
      return null;
    }
    Chunk chunk = chunk(chunkOf(id));
    return chunk == null ? null : (Core<?>) SLOT.getAcquire(chunk.slots, slotOf(id));
  }

  /**
   * The live objects: the numbers handed out less those gone. Computed, not counted, so that adding
   * and removing an object write no shared counter (the creator and the objects that stop run on
   * different workers). The lock keeps the freed chunks and the array of chunks in step; an object
   * being added or removed meanwhile may be counted or not.
   */
  long size() {
    lock.lock();
    try {
      long gone = freedChunks * CHUNK;
      for (Chunk chunk : chunks) {
        if (chunk != null) {
          gone += (int) GONE.getVolatile(chunk);
        }
      }
      return Math.max(0, lastId.get() - gone);
    } finally {
      lock.unlock();
    }
  }

  /** Visits the live objects (a weakly consistent view). */
  void forEach(Consumer<Core<?>> action) {
    for (Chunk chunk : chunks) {
      if (chunk != null) {
        for (int i = 0; i < CHUNK; i++) {
          Core<?> c = (Core<?>) SLOT.getAcquire(chunk.slots, i);
          if (c != null) {
            action.accept(c);
          }
        }
      }
    }
  }

  private @Nullable Chunk chunk(int c) {
    @Nullable Chunk[] cs = chunks;
    return c < cs.length ? cs[c] : null;
  }

  /** The chunk of {@code id}, made if it is not there yet (it cannot have been freed). */
  private Chunk chunkFor(long id) {
    int c = chunkOf(id);
    Chunk chunk = chunk(c);
    if (chunk != null) {
      return chunk;
    }
    lock.lock();
    try {
      @Nullable Chunk[] cs = chunks;
      if (c >= cs.length) {
        cs = java.util.Arrays.copyOf(cs, Math.max(c + 1, cs.length * 2));
      }
      chunk = cs[c];
      if (chunk == null) {
        chunk = new Chunk();
        cs[c] = chunk;
      }
      chunks = cs; // publish the new chunk (and the grown array)
      return chunk;
    } finally {
      lock.unlock();
    }
  }

  private static int chunkOf(long id) {
    long c = (id - 1) / CHUNK;
    if (c >= Integer.MAX_VALUE) {
      throw new IllegalStateException("object numbers exhausted at " + id);
    }
    return (int) c;
  }

  private static int slotOf(long id) {
    return (int) ((id - 1) % CHUNK);
  }
}
