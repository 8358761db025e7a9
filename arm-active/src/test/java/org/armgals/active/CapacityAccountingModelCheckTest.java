package org.armgals.active;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.armgals.active.spi.ObjectListener;
import org.jetbrains.lincheck.datastructures.ModelCheckingOptions;
import org.jetbrains.lincheck.datastructures.Operation;
import org.jetbrains.lincheck.datastructures.Param;
import org.jetbrains.lincheck.datastructures.ThreadIdGen;
import org.jetbrains.lincheck.datastructures.Validate;
import org.junit.jupiter.api.Test;

/**
 * Lincheck model checking of the capacity accounting of a full buffer under each overflow policy
 * but block (which parks its sender, out of reach of the model checker): senders race with workers
 * on a buffer of one place. At the end of each scenario every event sent must be exactly one of
 * processed, dropped (heard by the object's listener) or rejected (thrown at its sender), the
 * runtime's counters must agree, and the queue depth never leaves {@code [0, capacity]}.
 */
class CapacityAccountingModelCheckTest {
  static final int CAPACITY = 1;

  @Test
  void rejectedEventsAreNeverProcessedAndProcessedPlusRejectedIsSent() {
    check(Reject.class);
  }

  @Test
  void droppedNewestEventsAreNeverProcessedAndProcessedPlusDroppedIsSent() {
    check(DropNewest.class);
  }

  @Test
  void droppedOldestEventsAreNeverProcessedAndProcessedPlusDroppedIsSent() {
    check(DropOldest.class);
  }

  private static void check(Class<? extends FullBuffer> scenario) {
    new ModelCheckingOptions()
        .iterations(3)
        .invocationsPerIteration(60)
        .threads(2)
        .actorsPerThread(3)
        .actorsBefore(0)
        .actorsAfter(0)
        .sequentialSpecification(Bounds.class)
        .check(scenario);
  }

  /** One object with a buffer of {@link #CAPACITY} and the given policy, made per scenario. */
  public abstract static class FullBuffer {
    private final HandDrivenRuntime runtime = new HandDrivenRuntime();
    private final Journal journal = new Journal();
    private final ConcurrentLinkedQueue<Tagged> dropped = new ConcurrentLinkedQueue<>();
    private final ConcurrentLinkedQueue<Tagged> rejected = new ConcurrentLinkedQueue<>();
    private final OverflowPolicy policy;
    private final Core<Journal> object;
    private final int[] sent = new int[8];

    FullBuffer(OverflowPolicy policy) {
      this.policy = policy;
      ObjectListener listener =
          new ObjectListener() {
            @Override
            public void onDropped(Address object, Event event, OverflowPolicy p) {
              dropped.add((Tagged) event);
            }
          };
      object =
          runtime.spawn(
              journal,
              ObjectConfig.asynchronous()
                  .withCapacity(CAPACITY)
                  .withOverflow(policy)
                  .withListener(listener));
    }

    /** A one-way event from test thread {@code thread}; a refused one is written down. */
    @Operation
    public void send(@Param(gen = ThreadIdGen.class) int thread) {
      Tagged t = new Tagged(object.address(), thread, ++sent[thread]);
      try {
        object.send(t);
      } catch (BufferFullException e) {
        rejected.add(t);
      }
    }

    /** One worker step. */
    @Operation
    public void work() {
      runtime.runOne();
    }

    @Operation
    public boolean queueDepthWithinCapacity() {
      int depth = object.queueDepth();
      return depth >= 0 && depth <= CAPACITY;
    }

    @Validate
    public void everyEventSentIsProcessedDroppedOrRejectedExactlyOnce() {
      runtime.drain();
      if (object.queueDepth() != 0) {
        throw new AssertionError(
            object.queueDepth() + " event(s) left queued with the object idle (a lost wake-up)");
      }
      List<Tagged> processed = journal.processed();
      Ledger.assertEachSentEventAccountedForOnce(
          sent, processed, new ArrayList<>(dropped), new ArrayList<>(rejected));
      if (policy instanceof OverflowPolicy.Reject ? !dropped.isEmpty() : !rejected.isEmpty()) {
        throw new AssertionError(
            "policy " + policy + " dropped " + dropped + " and rejected " + rejected);
      }
      RuntimeStats stats = runtime.stats();
      if (stats.processed() != processed.size()
          || stats.dropped() != dropped.size()
          || stats.rejected() != rejected.size()) {
        throw new AssertionError(
            "runtime counters "
                + stats
                + " disagree with what the test saw: processed "
                + processed.size()
                + ", dropped "
                + dropped.size()
                + ", rejected "
                + rejected.size());
      }
      if (!runtime.failures().isEmpty()) {
        throw new AssertionError("the object failed: " + runtime.failures());
      }
      object.stop();
      runtime.drain();
    }
  }

  /** {@link FullBuffer} rejecting. */
  public static final class Reject extends FullBuffer {
    public Reject() {
      super(OverflowPolicy.reject());
    }
  }

  /** {@link FullBuffer} dropping the newest event. */
  public static final class DropNewest extends FullBuffer {
    public DropNewest() {
      super(OverflowPolicy.dropNewest());
    }
  }

  /** {@link FullBuffer} dropping the oldest event. */
  public static final class DropOldest extends FullBuffer {
    public DropOldest() {
      super(OverflowPolicy.dropOldest());
    }
  }

  /** The sequential specification: nothing observable but the depth bound. */
  public static final class Bounds {
    public void send(int thread) {}

    public void work() {}

    public boolean queueDepthWithinCapacity() {
      return true;
    }
  }
}
