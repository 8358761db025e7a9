package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
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
 * slot is set by a release store and cleared by a compare-and-set, and each chunk counts its
 * removals. Only making a chunk, growing the array of chunks and freeing a chunk take a lock, once
 * per {@link #CHUNK} objects (an object created and stopped per message, as in a creation workload,
 * made the lock per object contended: the creator and the stopping objects run on different
 * workers).
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

  /** {@link #CHUNK} slots and how many of their objects have been removed. */
  private static final class Chunk {
    final @Nullable Core<?>[] slots = new Core<?>[CHUNK];

    @SuppressWarnings("unused") // accessed through GONE
    volatile int gone;
  }

  private final ReentrantLock lock = new ReentrantLock();
  private volatile @Nullable Chunk[] chunks = new Chunk[0];
  private final AtomicLong lastId = new AtomicLong();
  private final LongAdder count = new LongAdder();

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
    count.increment();
    return core;
  }

  /** Removes {@code core} if it is there. */
  void remove(Core<?> core) {
    Chunk chunk = chunk(chunkOf(core.id));
    if (chunk == null || !SLOT.compareAndSet(chunk.slots, slotOf(core.id), core, (Core<?>) null)) {
      return;
    }
    count.decrement();
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

  long size() {
    return count.sum();
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
