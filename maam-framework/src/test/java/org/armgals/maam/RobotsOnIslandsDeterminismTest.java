package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.gals.Island;
import org.armgals.gals.ReactiveEntity;
import org.armgals.kernel.AdaptationPoint;
import org.junit.jupiter.api.Test;

/**
 * Robots on islands stepped by hand are deterministic: five robots with random programs on two
 * islands, talking to each other and adapted on the way, give the same per-cycle traces (and
 * hashes) on every run and for 1, 2, 4 and 8 workers.
 */
class RobotsOnIslandsDeterminismTest {

  /** Runs the scenario; the traces of both islands, then their hashes. */
  private static List<String> scenario(int workers) {
    ActiveRuntime runtime = ActiveRuntime.builder().name("det").workers(workers).jmx(false).build();
    TestRobot.TestTime time = new TestRobot.TestTime();
    try (Island fast =
            Island.builder("fast", runtime)
                .period(Duration.ofMillis(10))
                .timeSource(time)
                .tracing(true)
                .jmx(false)
                .build();
        Island slow =
            Island.builder("slow", runtime)
                .period(Duration.ofMillis(20))
                .adaptationPoint(AdaptationPoint.END_OF_CYCLE)
                .timeSource(time)
                .tracing(true)
                .jmx(false)
                .build()) {
      List<LinkedRobot> robots = new ArrayList<>();
      List<ReactiveEntity<AbstractRobot>> entities = new ArrayList<>();
      for (int i = 0; i < 5; i++) {
        LinkedRobot robot = LinkedRobot.create("r" + i, time);
        RandomProgram program = new RandomProgram(i, 3, 5);
        program.schemas.forEach(robot::addSchema);
        program.connectors.forEach(robot::addConnector);
        // what the robot receives flows into its random program, through a kept-free input
        robot.addConnector(
            new Derivator(
                new PortRef("inbox", LinkedRobot.LINK),
                new PortRef("s0m0", Node.in(RandomProgram.FREE_INPUTS))));
        robots.add(robot);
        entities.add(robot.start(i < 3 ? fast : slow));
      }
      for (int i = 0; i < 5; i++) {
        robots.get(i).peers.add(entities.get((i + 1) % 5));
        robots.get(i).peers.add(entities.get((i + 3) % 5));
      }
      for (int k = 1; k <= 40; k++) {
        if (k % 10 == 0) {
          LinkedRobot robot = robots.get(k / 10);
          robot.request(new Adaptation.ChangeModule(robot.inbox(k)));
          robot.request(new Adaptation.RemoveSchema("schema" + k / 10));
        }
        fast.step();
        time.now += Duration.ofMillis(10).toNanos();
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

  @Test
  void robotsOnIslandsGiveTheSameTraceForAnyNumberOfWorkersAndOnEveryRun() {
    List<String> reference = scenario(1);
    assertThat(reference).hasSizeGreaterThan(100);
    assertThat(reference).anyMatch(l -> l.contains("adapt changeModule inbox"));
    assertThat(reference).anyMatch(l -> l.startsWith("slow ") && l.contains(" in [Num[value="));
    assertThat(reference).anyMatch(l -> l.contains("s0m0.out"));
    for (int workers : new int[] {1, 2, 4, 8}) {
      for (int run = 0; run < 2; run++) {
        assertThat(scenario(workers)).as("%d workers, run %d", workers, run).isEqualTo(reference);
      }
    }
  }
}
