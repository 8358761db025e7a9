package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.TimeSource;
import org.armgals.gals.Island;
import org.armgals.gals.IslandStats;
import org.armgals.gals.ReactiveEntity;
import org.armgals.kernel.AdaptationPoint;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * A robot as a reactive entity of an island: one cycle per release, adaptations at the island's
 * point and on its budget, the island's trace, and robots of two islands talking asynchronously.
 */
class RobotOnIslandTest {

  private static final Duration PERIOD = Duration.ofMillis(10);

  private final ActiveRuntime runtime =
      ActiveRuntime.builder().name("robots").workers(2).jmx(false).build();

  @AfterEach
  void close() {
    runtime.close();
  }

  private Island island(String name, Duration period, AdaptationPoint point, TimeSource time) {
    return Island.builder(name, runtime)
        .period(period)
        .adaptationPoint(point)
        .timeSource(time)
        .tracing(true)
        .jmx(false)
        .build();
  }

  @Test
  void aRobotOnAnIslandRunsOneCyclePerReleaseAndTracesEachCycle() {
    TestRobot.TestTime time = new TestRobot.TestTime();
    try (Island island = island("i", PERIOD, AdaptationPoint.BEGIN_OF_CYCLE, time)) {
      LinkedRobot robot = LinkedRobot.create("r", time);
      ReactiveEntity<AbstractRobot> entity = robot.start(island);
      island.step(5);

      assertThat(entity.name()).isEqualTo("r");
      assertThat(island.entities()).containsExactly(entity);
      assertThat(robot.cycles()).isEqualTo(5);
      assertThat(robot.fake.cycles()).isEqualTo(5);
      assertThat(robot.sums).containsExactly(0, 0, 0, 0, 0);
      assertThat(island.trace())
          .hasSize(5)
          .first()
          .isEqualTo("i 1 r main: cycle 1 [Emission[port=inbox.link, signal=Num[value=0]]]");
      assertThat(island.trace().get(4)).startsWith("i 5 r main: cycle 5 ");
      assertThat(robot.adaptationPoint()).isEqualTo(AdaptationPoint.BEGIN_OF_CYCLE);
    }
  }

  @Test
  void aRobotOnAnIslandIsSteppedByItsIslandOnly() {
    TestRobot.TestTime time = new TestRobot.TestTime();
    try (Island island = island("i", PERIOD, AdaptationPoint.BEGIN_OF_CYCLE, time)) {
      LinkedRobot robot = LinkedRobot.create("r", time);
      robot.start(island);

      assertThatThrownBy(robot::cycle)
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("robot r runs on island i");
      assertThatThrownBy(() -> robot.start(island))
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("already runs on island i");
      assertThatThrownBy(() -> robot.emit(island.entities().get(0), new Num(1)))
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("during one of its cycles");
      assertThat(robot.received()).isEmpty();
    }
  }

  @Test
  void anAdaptationPointOnArrivalIsRefused() {
    LinkedRobot robot = LinkedRobot.create("r", new TestRobot.TestTime());
    assertThatThrownBy(() -> robot.point(AdaptationPoint.ON_ARRIVAL))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("ON_ARRIVAL")
        .hasMessageContaining("BEGIN_OF_CYCLE or END_OF_CYCLE");
  }

  /** Requests a new inbox bias between the first and the second cycle; the sums of 3 cycles. */
  private static List<Integer> sumsAfterAdaptingBeforeTheSecondCycle(
      Island island, LinkedRobot robot) {
    robot.start(island);
    island.step();
    robot.request(new Adaptation.ChangeModule(robot.inbox(100)));
    island.step(2);
    return robot.sums; // the end of a cycle happens-before step returns
  }

  @Test
  void atTheBeginningOfACycleAnAdaptationShapesThatCycle() {
    TestRobot.TestTime time = new TestRobot.TestTime();
    try (Island island = island("i", PERIOD, AdaptationPoint.BEGIN_OF_CYCLE, time)) {
      LinkedRobot robot = LinkedRobot.create("r", time);
      assertThat(sumsAfterAdaptingBeforeTheSecondCycle(island, robot)).containsExactly(0, 100, 100);
      assertThat(island.trace()).contains("i 2 r adapt changeModule inbox");
      assertThat(island.stats().adaptations()).isEqualTo(1);
    }
  }

  @Test
  void atTheEndOfACycleAnAdaptationShapesTheNextCycle() {
    TestRobot.TestTime time = new TestRobot.TestTime();
    try (Island island = island("i", PERIOD, AdaptationPoint.END_OF_CYCLE, time)) {
      LinkedRobot robot = LinkedRobot.create("r", time);
      assertThat(sumsAfterAdaptingBeforeTheSecondCycle(island, robot)).containsExactly(0, 0, 100);
      assertThat(island.trace()).contains("i 2 r adapt changeModule inbox");
    }
  }

  @Test
  void theBehavioralMetasRequestsAreAppliedAtTheIslandsPoint() {
    for (AdaptationPoint point :
        List.of(AdaptationPoint.BEGIN_OF_CYCLE, AdaptationPoint.END_OF_CYCLE)) {
      TestRobot.TestTime time = new TestRobot.TestTime();
      try (Island island = island("i", PERIOD, point, time)) {
        LinkedRobot robot = LinkedRobot.create("r", time);
        robot.bmeta(
            (report, requests) -> {
              if (report.cycle() == 1) {
                requests.accept(new Adaptation.ChangeModule(robot.inbox(100)));
              }
            });
        robot.start(island);
        island.step(3);

        // requested in cycle 1: applied at its end, or at the beginning of cycle 2
        assertThat(robot.sums).as(point.toString()).containsExactly(0, 100, 100);
        long appliedAt = point == AdaptationPoint.END_OF_CYCLE ? 1 : 2;
        assertThat(island.trace())
            .as(point.toString())
            .contains("i " + appliedAt + " r adapt changeModule inbox");
      }
    }
  }

  @Test
  void theTimeAnAdaptationTakesCountsAgainstTheIslandsBudget() {
    TestRobot.TestTime time = new TestRobot.TestTime();
    boolean[] slow = {false}; // read by the island's thread, between instants
    Scheduler scheduler =
        (schemas, connectors) -> {
          if (slow[0]) {
            time.now += Duration.ofMillis(8).toNanos();
          }
          return Scheduler.topological().schedule(schemas, connectors);
        };
    try (Island island = island("i", PERIOD, AdaptationPoint.END_OF_CYCLE, time)) {
      LinkedRobot robot = LinkedRobot.create("r", time, MetaRobot.create(scheduler));
      robot.addBehaviorModule(new Work("work", time, Duration.ofMillis(4)));
      robot.start(island);
      island.step(); // 4 ms of a 10 ms budget
      slow[0] = true;
      robot.request(
          new Adaptation.AddSchema(
              Schema.builder("extra").add(new Work("extra", time, Duration.ZERO)).build()));
      island.step(); // 4 + 8 ms: over budget because of the rescheduling
      island.step();

      IslandStats stats = island.stats();
      assertThat(stats.instants()).isEqualTo(3);
      assertThat(stats.adaptations()).isEqualTo(1);
      assertThat(stats.adaptationMax()).isEqualTo(Duration.ofMillis(8));
      assertThat(stats.cycleMax()).isEqualTo(Duration.ofMillis(12));
      assertThat(stats.overruns()).isEqualTo(1);
      assertThat(stats.adaptationOverruns()).isEqualTo(1);
      assertThat(robot.schedule().names()).contains("extra");
    }
  }

  @Test
  void aRejectedAdaptationIsTheRobotsAndIsTracedInItsNextCycle() {
    TestRobot.TestTime time = new TestRobot.TestTime();
    try (Island island = island("i", PERIOD, AdaptationPoint.BEGIN_OF_CYCLE, time)) {
      LinkedRobot robot = LinkedRobot.create("r", time);
      robot.start(island);
      robot.request(new Adaptation.RemoveSchema("absent"));
      island.step();

      assertThat(robot.rejectedAdaptations()).isEqualTo(1);
      assertThat(island.stats().failures()).isZero();
      assertThat(island.trace()).startsWith("i 1 r adapt removeSchema absent");
      assertThat(island.trace().get(1)).startsWith("i 1 r main: rejected removeSchema absent: ");
    }
  }

  @Test
  void robotsOnIslandsOfDifferentPeriodsTalkAsynchronously() {
    TestRobot.TestTime time = new TestRobot.TestTime();
    try (Island fast = island("fast", PERIOD, AdaptationPoint.BEGIN_OF_CYCLE, time);
        Island slow = island("slow", Duration.ofMillis(30), AdaptationPoint.END_OF_CYCLE, time)) {
      LinkedRobot ping = LinkedRobot.create("ping", time);
      LinkedRobot pong = LinkedRobot.create("pong", time);
      ReactiveEntity<AbstractRobot> pingEntity = ping.start(fast);
      ReactiveEntity<AbstractRobot> pongEntity = pong.start(slow);
      ping.peers.add(pongEntity);
      pong.peers.add(pingEntity);
      for (int k = 1; k <= 9; k++) {
        fast.step();
        if (k % 3 == 0) {
          slow.step();
        }
      }

      // ping sends 7 (f(0)) three times per slow period: pong takes the three at its next release
      // and answers f(21) = 658, which ping takes at its next release; f(v) = (31 v + 7) mod 1000
      assertThat(pong.sums).containsExactly(21, 405 + 7 + 7, 883 + 7 + 7);
      assertThat(ping.sums).containsExactly(0, 0, 0, 658, 0, 0, 996, 0, 0);
      assertThat(slow.trace())
          .contains("slow 1 pong in [Num[value=7], Num[value=7], Num[value=7]]");
    }
  }

  @Test
  void onARealTimeIslandARobotRunsAtTheIslandsPaceAndAdaptsThere() throws InterruptedException {
    CountDownLatch twenty = new CountDownLatch(20);
    Island island =
        Island.builder("rt", runtime).period(Duration.ofMillis(1)).tracing(true).jmx(false).build();
    LinkedRobot robot = LinkedRobot.create("r", TimeSource.system());
    try {
      robot.bmeta(
          (report, requests) -> {
            if (report.cycle() == 5) {
              requests.accept(new Adaptation.ChangeModule(robot.inbox(100)));
            }
            twenty.countDown();
          });
      robot.start(island);
      island.start();
      assertThat(twenty.await(10, TimeUnit.SECONDS)).isTrue();
    } finally {
      island.close(); // waits for the cycle in progress
    }

    IslandStats stats = island.stats();
    assertThat(robot.cycles()).isEqualTo(stats.instants()).isGreaterThanOrEqualTo(20);
    assertThat(stats.adaptations()).isEqualTo(1);
    assertThat(stats.jitterMax()).isGreaterThanOrEqualTo(stats.jitterP50());
    // requested in cycle 5, applied at the beginning of cycle 6 (the island default)
    assertThat(robot.sums.subList(0, 5)).containsOnly(0);
    assertThat(robot.sums.subList(5, 20)).containsOnly(100);
    assertThat(island.trace()).anyMatch(l -> l.endsWith(" r adapt changeModule inbox"));
  }

  /** A perceptor that takes {@code cost} of the test's time. */
  private record Work(String name, TestRobot.TestTime time, Duration cost) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of();
    }

    @Override
    public void perceive(org.armgals.maam.spi.Body body, Outputs out) {
      time.now += cost.toNanos();
    }
  }
}
