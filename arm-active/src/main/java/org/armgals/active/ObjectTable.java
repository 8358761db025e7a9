package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.jspecify.annotations.Nullable;

/**
 * The live objects of a runtime, indexed by object number: chunks of {@link #CHUNK} slots, so an
 * object costs one reference here (a hash map entry and its boxed key would cost about 56 bytes, a
 * quarter of the idle-object budget). A chunk whose objects have all been numbered and have all
 * stopped is freed.
 *
 * <p>Lookups are lock-free (an acquire read of the slot); numbering, insertion and removal take a
 * lock, uncontended in practice.
 */
final class ObjectTable {
  static final int CHUNK = 1024;
  private static final VarHandle SLOT = MethodHandles.arrayElementVarHandle(Core[].class);

  private final ReentrantLock lock = new ReentrantLock();
  private volatile @Nullable Core<?>[][] chunks = new Core<?>[0][];
  private int[] live = new int[0];
  private long lastId;
  private volatile long count;

  /** Numbers a new object and stores the one {@code make} builds with that number. */
  <S> Core<S> add(java.util.function.LongFunction<Core<S>> make) {
    lock.lock();
    try {
      long id = ++lastId;
      Core<S> core = make.apply(id);
      int c = chunkOf(id);
      @Nullable Core<?>[][] cs = chunks;
      if (c >= cs.length) {
        cs = java.util.Arrays.copyOf(cs, Math.max(c + 1, cs.length * 2));
        live = java.util.Arrays.copyOf(live, cs.length);
        chunks = cs;
      }
      Core<?>[] chunk = cs[c];
      if (chunk == null) {
        chunk = new Core<?>[CHUNK];
        cs[c] = chunk;
        chunks = cs; // publish the new chunk
      }
      SLOT.setRelease(chunk, slotOf(id), core);
      live[c]++;
      count++;
      return core;
    } finally {
      lock.unlock();
    }
  }

  /** Removes {@code core} if it is there. */
  void remove(Core<?> core) {
    lock.lock();
    try {
      int c = chunkOf(core.id);
      @Nullable Core<?>[][] cs = chunks;
      Core<?>[] chunk = c < cs.length ? cs[c] : null;
      if (chunk == null || chunk[slotOf(core.id)] != core) {
        return;
      }
      SLOT.setRelease(chunk, slotOf(core.id), (Core<?>) null);
      count--;
      if (--live[c] == 0 && lastId >= (long) (c + 1) * CHUNK) {
        cs[c] = null;
        chunks = cs;
      }
    } finally {
      lock.unlock();
    }
  }

  /** The live object numbered {@code id}, or null. */
  @Nullable Core<?> get(long id) {
    if (id < 1) {
      return null;
    }
    int c = chunkOf(id);
    @Nullable Core<?>[][] cs = chunks;
    Core<?>[] chunk = c < cs.length ? cs[c] : null;
    return chunk == null ? null : (Core<?>) SLOT.getAcquire(chunk, slotOf(id));
  }

  long size() {
    return count;
  }

  /** Visits the live objects (a weakly consistent view). */
  void forEach(Consumer<Core<?>> action) {
    for (Core<?>[] chunk : chunks) {
      if (chunk != null) {
        for (int i = 0; i < CHUNK; i++) {
          Core<?> c = (Core<?>) SLOT.getAcquire(chunk, i);
          if (c != null) {
            action.accept(c);
          }
        }
      }
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
