package org.armgals.active;

import java.util.List;
import org.jetbrains.lincheck.datastructures.ModelCheckingOptions;
import org.jetbrains.lincheck.datastructures.Operation;
import org.jetbrains.lincheck.datastructures.Param;
import org.jetbrains.lincheck.datastructures.ThreadIdGen;
import org.jetbrains.lincheck.datastructures.Validate;
import org.junit.jupiter.api.Test;

/**
 * Lincheck model checking of one asynchronous object: its Vyukov buffer, its SCHEDULED flag and the
 * idle re-check, under every interleaving Lincheck explores of concurrent senders, workers (any
 * test thread may run an activation, as dispatcher workers do) and synchronized requests whose
 * callers help run the object until their reply comes.
 *
 * <p>Linearizability against {@link Counter} checks that a synchronized request sees exactly the
 * events sent before it; the validation at the end of each scenario runs the object until nothing
 * is scheduled and checks that nothing is left queued (a lost wake-up leaves an event queued with
 * the object idle) and that each event was processed once, in its sender's order.
 */
class SchedulingModelCheckTest {
  static final int CAPACITY = 16;

  @Test
  void everyEventSentIsProcessedExactlyOnceInSenderOrderWithNoLostWakeUp() {
    new ModelCheckingOptions()
        .iterations(6)
        .invocationsPerIteration(100)
        .threads(3)
        .actorsPerThread(2)
        .actorsBefore(0)
        .actorsAfter(0)
        .sequentialSpecification(Counter.class)
        .check(OneObject.class);
  }

  /** The object under test, made anew for every scenario Lincheck runs. */
  public static final class OneObject {
    private final HandDrivenRuntime runtime = new HandDrivenRuntime();
    private final Journal journal = new Journal();
    private final Core<Journal> object =
        runtime.spawn(
            journal,
            ObjectConfig.asynchronous()
                .withCapacity(CAPACITY)
                .withOverflow(OverflowPolicy.reject()));
    private final int[] sent = new int[8];

    /** A one-way event from test thread {@code thread}. */
    @Operation
    public void send(@Param(gen = ThreadIdGen.class) int thread) {
      object.send(new Tagged(object.address(), thread, ++sent[thread]));
    }

    /** A synchronized request: how many events were processed before it. */
    @Operation
    public int processedBefore() {
      FutureValue<Integer> f = object.call(Journal::size);
      while (!f.isDone()) {
        runtime.runOne();
      }
      return f.getValue();
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
    public void nothingIsLeftQueuedAndEachEventWasProcessedOnceInOrder() {
      runtime.drain();
      if (object.queueDepth() != 0) {
        throw new AssertionError(
            object.queueDepth() + " event(s) left queued with the object idle (a lost wake-up)");
      }
      Ledger.assertEachSentEventAccountedForOnce(sent, journal.processed(), List.of(), List.of());
      if (!runtime.failures().isEmpty()) {
        throw new AssertionError("the object failed: " + runtime.failures());
      }
      object.stop();
      runtime.drain();
    }
  }

  /** The sequential specification: a count of the events sent. */
  public static final class Counter {
    private int sent;

    public void send(int thread) {
      sent++;
    }

    public int processedBefore() {
      return sent;
    }

    public void work() {}

    public boolean queueDepthWithinCapacity() {
      return true;
    }
  }
}
