package org.armgals.bench.savina;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.lang.ref.Reference;

/**
 * Measures the heap that idle objects cost their runtime.
 *
 * <p>The servants and the array of handles are allocated <em>before</em> the first measurement, so
 * the difference between the two measurements is what the runtime adds per object: its object
 * record, buffer, registration, reference, and anything the implementation needs around the servant
 * (for Pekko, the behavior that holds it). The servant's own bytes are thereby subtracted without
 * estimating them.
 */
public final class HeapProbe {
  private static final int MAX_COLLECTIONS = 10;
  private static final long SETTLED_BYTES = 64 * 1024;

  private HeapProbe() {}

  /**
   * The heap bytes per object of {@code count} idle objects made by {@code objects}.
   *
   * @throws IllegalStateException an object did not process exactly one message
   */
  public static double bytesPerIdleObject(IdleObjects objects, int count) throws Exception {
    if (count < 1) {
      throw new IllegalArgumentException("count must be >= 1, was " + count);
    }
    Idle[] servants = new Idle[count];
    for (int i = 0; i < count; i++) {
      servants[i] = new Idle();
    }
    Object[] handles = new Object[count];
    long before = usedAfterGc();
    objects.populate(servants, handles);
    long after = usedAfterGc();
    for (int i = 0; i < count; i++) {
      if (servants[i].touches() != 1 || handles[i] == null) {
        Check.equal("mem: messages seen by idle object " + i, 1, servants[i].touches());
        Check.state(handles[i] != null, "mem: no handle for idle object " + i);
      }
    }
    Reference.reachabilityFence(servants);
    Reference.reachabilityFence(handles);
    return (double) (after - before) / count;
  }

  /**
   * The used heap after full collections: collects until two readings are within {@value
   * #SETTLED_BYTES} bytes of each other (at most {@value #MAX_COLLECTIONS} times).
   */
  static long usedAfterGc() {
    MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
    long previous = Long.MAX_VALUE;
    long used = Long.MAX_VALUE;
    for (int i = 0; i < MAX_COLLECTIONS; i++) {
      System.gc();
      used = memory.getHeapMemoryUsage().getUsed();
      if (Math.abs(previous - used) <= SETTLED_BYTES) {
        break;
      }
      previous = used;
    }
    return used;
  }
}
