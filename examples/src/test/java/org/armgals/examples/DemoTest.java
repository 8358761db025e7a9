package org.armgals.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.armgals.active.WaitCycleException;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The demo, run once, does what it prints. */
class DemoTest {
  private static Demo.Outcome outcome;
  private static String printed;

  @BeforeAll
  static void runTheDemo() {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    try (PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
      outcome = Demo.run(out);
    }
    printed = bytes.toString(StandardCharsets.UTF_8);
  }

  @Test
  void bufferHandsEveryItemOnceInPerProducerOrderAndNeverHoldsMoreThanItsCapacity() {
    GuardedBufferDemo.Result b = outcome.buffer();
    assertThat(b.taken())
        .containsExactlyInAnyOrder("a1", "a2", "a3", "a4", "a5", "b1", "b2", "b3", "b4", "b5");
    assertThat(GuardedBufferDemo.inOrder(b.taken())).isTrue();
    assertThat(b.mostHeld()).isBetween(1, b.capacity());
  }

  @Test
  void futuresCarryTheValueTheFailureAndReportTheWaitCycle() {
    assertThat(outcome.futures().order()).isEqualTo("3 x widget = 36");
    assertThat(outcome.futures().failure()).isEqualTo("no such item: gizmo");
    WaitCycleException cycle = outcome.futures().cycle();
    assertThat(cycle).isNotNull();
    assertThat(cycle.cycle()).hasSize(3);
    assertThat(cycle.cycle().get(0)).isEqualTo(cycle.cycle().get(2));
  }

  @Test
  void reactiveTraceIsEmittedAtKSeenAtKPlusOneAndTheSynchronousFutureTwoInstantsLater() {
    assertThat(outcome.reactive().instants())
        .containsExactly(
            "instant 1: sensor emits 10; controller asks the sensor for its offset",
            "instant 2: sensor emits 20; controller sees 10 (emitted at 1);"
                + " offset not there yet, the controller goes on",
            "instant 3: sensor emits 30; controller sees 20 (emitted at 2);"
                + " offset 7 arrived (asked at 1)",
            "instant 4: sensor emits 40; controller sees 30 (emitted at 3)");
  }

  @Test
  void failuresGoToTheHandlerAndTheRuntimeShutsDownCleanly() {
    // the gizmo fails in the catalog and in the desk; the cycle fails one or both players
    assertThat(outcome.handledFailures()).isBetween(3L, 4L);
    assertThat(outcome.stats().failures()).isEqualTo(outcome.handledFailures());
    assertThat(outcome.stats().dropped()).isZero();
    assertThat(outcome.cleanShutdown()).isTrue();
  }

  @Test
  void lastLineIsTheRuntimeStats() {
    assertThat(printed).endsWith(outcome.stats() + System.lineSeparator());
  }
}
