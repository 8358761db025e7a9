package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.kernel.AdaptationPoint;
import org.junit.jupiter.api.Test;

/**
 * With islands stepped by hand, the whole system is deterministic: the same scenario gives the same
 * per-cycle traces (and hashes) on every run and for 1, 2, 4 and 8 workers.
 */
class DeterminismTest {

  /** What one entity keeps: a value it mixes its inputs into, and what it awaits. */
  static final class Cell {
    long value;
    final List<AwaitedValue<Long>> awaited = new ArrayList<>();
  }

  /** Runs the scenario; the traces of both islands, then their hashes. */
  private static List<String> scenario(int workers) {
    ActiveRuntime runtime = Fixtures.runtime("det", workers);
    try (Island fast =
            Island.builder("fast", runtime).period(Duration.ofMillis(10)).tracing(true).build();
        Island slow =
            Island.builder("slow", runtime)
                .period(Duration.ofMillis(20))
                .adaptationPoint(AdaptationPoint.END_OF_CYCLE)
                .tracing(true)
                .build()) {
      List<ReactiveEntity<Cell>> cells = new ArrayList<>();
      List<ReactiveEntity<Cell>> deliberators = new ArrayList<>();
      for (int i = 0; i < 3; i++) {
        int me = i;
        deliberators.add(
            slow.spawn(
                "d" + i,
                new Cell(),
                c -> {
                  Cell s = c.state();
                  for (Object in : c.inputs()) {
                    s.value = s.value * 31 + (Long) in;
                  }
                  for (AwaitedValue<Long> a : s.awaited) {
                    c.trace("awaited " + a.status() + (a.isPending() ? "" : " " + describe(a)));
                  }
                  s.awaited.removeIf(a -> !a.isPending());
                  if (c.instant() % 2 == 1) {
                    ReactiveEntity<Cell> target = cells.get((int) (c.instant() + me) % 6);
                    s.awaited.add(c.call(target, t -> t.value, Duration.ofMillis(30)));
                  }
                  c.trace("value " + s.value);
                }));
      }
      for (int i = 0; i < 6; i++) {
        int me = i;
        cells.add(
            fast.spawn(
                "c" + i,
                new Cell(),
                c -> {
                  Cell s = c.state();
                  for (Object in : c.inputs()) {
                    s.value = s.value * 17 + (Long) in;
                  }
                  s.value += me;
                  for (int j = 1; j <= 2; j++) {
                    c.emit(cells.get((me + j) % 6), s.value % 1000);
                  }
                  c.emit(deliberators.get(me % 3), s.value % 100);
                  c.trace("value " + s.value);
                }));
      }
      for (int k = 1; k <= 40; k++) {
        if (k % 10 == 0) {
          cells.get(k % 6).adapt("reset", s -> s.value = 0);
          deliberators.get(k % 3).adapt("double", s -> s.value *= 2);
        }
        fast.step();
        if (k % 2 == 0) {
          slow.step();
        }
      }
      List<String> out = new ArrayList<>(fast.trace());
      out.addAll(slow.trace());
      out.add(fast.traceHash());
      out.add(slow.traceHash());
      return out;
    } finally {
      runtime.close();
    }
  }

  private static String describe(AwaitedValue<Long> a) {
    return a.status() == AwaitedValue.Status.AVAILABLE ? String.valueOf(a.value()) : "";
  }

  @Test
  void sameScenarioGivesTheSameTraceForAnyNumberOfWorkersAndOnEveryRun() {
    List<String> reference = scenario(1);
    assertThat(reference).hasSizeGreaterThan(400);
    assertThat(reference).anyMatch(l -> l.contains("awaited AVAILABLE"));
    assertThat(reference).anyMatch(l -> l.contains("adapt reset"));
    for (int workers : new int[] {1, 2, 4, 8}) {
      for (int run = 0; run < 2; run++) {
        assertThat(scenario(workers)).as("%d workers, run %d", workers, run).isEqualTo(reference);
      }
    }
  }
}
