package org.armgals.active;

import static java.util.Objects.requireNonNull;
import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import org.jetbrains.lincheck.datastructures.Operation;
import org.jetbrains.lincheck.datastructures.Param;
import org.jetbrains.lincheck.datastructures.StressOptions;
import org.jetbrains.lincheck.datastructures.ThreadIdGen;
import org.jetbrains.lincheck.datastructures.Validate;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.Test;

/**
 * Lincheck stress mode on one asynchronous object of a real runtime (worker virtual threads, spin
 * and park): test threads send one-way events and synchronized requests concurrently, and the
 * results must be linearizable against {@link SchedulingModelCheckTest.Counter}. After each
 * scenario every event sent must have been processed once, in its sender's order, and the object is
 * stopped; the runtime is shut down at the end and must leave no worker alive.
 */
class ActiveObjectLincheckStressTest {
  private static final int CAPACITY = 64;
  private static final Duration PATIENCE = Duration.ofSeconds(10);
  private static @Nullable LiveRuntime live;

  static LiveRuntime live() {
    return requireNonNull(live, "live runtime");
  }

  @Test
  void concurrentSendsAndRequestsToOneObjectAreLinearizableAndEachProcessedOnce() {
    try (LiveRuntime r = new LiveRuntime("lincheck-stress")) {
      live = r;
      new StressOptions()
          .iterations(20)
          .invocationsPerIteration(300)
          .threads(3)
          .actorsPerThread(3)
          .actorsBefore(1)
          .actorsAfter(1)
          .sequentialSpecification(SchedulingModelCheckTest.Counter.class)
          .check(OneLiveObject.class);
      assertThat(r.failures()).isEmpty();
      assertThat(r.runtime().stats().objects()).as("objects left unstopped").isZero();
    } finally {
      live = null;
    }
  }

  /** The object under test, spawned in the shared live runtime for every scenario. */
  public static final class OneLiveObject {
    private final Journal journal = new Journal();
    private final ActiveObject<Journal> object =
        live()
            .spawn(
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

    /** A synchronized request, waited for by necessity: how many events were processed before. */
    @Operation
    public int processedBefore() {
      return object.call(Journal::size).getValue(PATIENCE);
    }

    @Operation
    public boolean queueDepthWithinCapacity() {
      int depth = object.queueDepth();
      return depth >= 0 && depth <= CAPACITY;
    }

    @Validate
    public void eachEventWasProcessedOnceInSenderOrder() {
      List<Tagged> processed = object.call(j -> List.copyOf(j.processed())).getValue(PATIENCE);
      object.stop();
      Ledger.assertEachSentEventAccountedForOnce(sent, processed, List.of(), List.of());
    }
  }
}
