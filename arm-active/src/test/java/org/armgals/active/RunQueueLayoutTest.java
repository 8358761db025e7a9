package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.openjdk.jol.info.ClassLayout;
import org.openjdk.jol.info.FieldLayout;

/**
 * How the JVM lays out the run queue (decision 0081): producers write {@code last} on every object
 * they queue, the polling worker writes {@code first} and {@code polling} on every object it takes.
 */
class RunQueueLayoutTest {
  private static final int LINE = 64;

  private final ClassLayout layout = ClassLayout.parseClass(RunQueue.class);

  @Test
  void theProducersEndSharesNoLineWithTheConsumersWhereverTheQueueStarts() {
    FieldLayout last = field("last");
    for (String consumer : new String[] {"first", "polling"}) {
      FieldLayout c = field(consumer);
      // A gap of a whole line between the two fields' bytes keeps them apart at any start.
      assertThat(last.offset() - (c.offset() + c.size()))
          .as("bytes between %s and last", consumer)
          .isGreaterThanOrEqualTo(LINE);
    }
  }

  private FieldLayout field(String name) {
    return layout.fields().stream()
        .filter(f -> f.name().equals(name))
        .findFirst()
        .orElseThrow(() -> new AssertionError("no field " + name + " in " + layout.toPrintable()));
  }
}
