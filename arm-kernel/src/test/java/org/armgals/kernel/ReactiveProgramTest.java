package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.armgals.active.ShutdownMode;
import org.armgals.kernel.spi.InstantContext;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.kernel.spi.ReactiveProgram;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The contract of a reactive entity with a program and its behavioral meta (paper figure 8): the
 * meta is an asynchronous entity that never runs inside the base level's instant; in lock step an
 * adaptation decided on the notifications of instant {@code n} is applied at the adaptation point
 * of instant {@code n + k}, whatever the threads; a refusal is acknowledged; a meta that stops
 * answering leaves the base level running.
 */
class ReactiveProgramTest extends KernelFixture {

  /** The battery robot's program: works 0.01 each instant and writes down the mode it runs in. */
  static final class Worker implements ReactiveProgram {
    final List<String> modes = new CopyOnWriteArrayList<>();
    volatile Thread reacting;
    volatile boolean refuseEco;

    @Override
    public void react(InstantContext instant) {
      reacting = Thread.currentThread();
      try {
        modes.add(instant.instant() + ":" + ((PState) instant.state()).get("mode"));
        instant.apply("work", 0.01);
      } finally {
        reacting = null;
      }
    }

    @Override
    public void adapt(Adaptation adaptation) {
      if (refuseEco
          && adaptation instanceof Adaptation.ApplyBehavior a
          && a.behavior().equals("eco")) {
        throw new IllegalArgumentException("no eco mode on this robot");
      }
    }

    /** The first instant whose program ran in {@code mode}, 0 if none. */
    long firstInstantIn(String mode) {
      for (String m : modes) {
        if (m.endsWith(":" + mode)) {
          return Long.parseLong(m.substring(0, m.indexOf(':')));
        }
      }
      return 0;
    }
  }

  /** Switches its entity to eco once the battery is below 0.895 (seen at instant 11). */
  static MetaPolicy ecoBelow(AtomicBoolean done) {
    return (context, n) -> {
      if (n instanceof StateEvent s
          && s.observation().get("battery") instanceof Double b
          && b < 0.895
          && done.compareAndSet(false, true)) {
        context.adapt(s.entity(), new Adaptation.ApplyBehavior("eco", null));
      }
    };
  }

  private Entity robot(
      Kernel k,
      ManualClock clock,
      BehavioralMeta meta,
      Worker program,
      AdaptationPoint point,
      int lockStep,
      Duration timeout) {
    return robotKindOf(k)
        .newEntity(
            "robot",
            meta,
            EntityOptions.defaults()
                .withConfig(ObjectConfig.synchronous(clock))
                .withNotification(NotificationPolicy.statesOnly())
                .withAdaptationPoint(point)
                .withProgram(program)
                .withLockStep(lockStep, timeout));
  }

  private static StructuralMeta<PState> robotKindOf(Kernel k) {
    return k.newStructuralMeta("Robot", ROBOT, robotBehaviors());
  }

  /** Runs {@code instants} instants of the battery robot in a runtime of {@code workers}. */
  private List<String> run(int workers, AdaptationPoint point, int lockStep, int instants) {
    ActiveRuntime rt = ActiveRuntime.builder().workers(workers).jmx(false).build();
    try (Kernel k =
        StructuralMeta.bootstrap(rt, new KernelOptions(time, Duration.ofMillis(100), false))) {
      ManualClock clock = Clock.manual(Duration.ofMillis(10));
      BehavioralMeta meta =
          k.newBehavioralMeta("meta", ecoBelow(new AtomicBoolean()), Damping.none());
      Worker program = new Worker();
      robot(k, clock, meta, program, point, lockStep, Duration.ofSeconds(10));
      for (int i = 0; i < instants; i++) {
        clock.step();
      }
      return List.copyOf(program.modes);
    } finally {
      rt.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
    }
  }

  @ParameterizedTest(name = "{0} with latency {1}: first eco instant {2}")
  @CsvSource({
    "END_OF_CYCLE, 1, 13",
    "END_OF_CYCLE, 2, 14",
    "END_OF_CYCLE, 3, 15",
    "BEGIN_OF_CYCLE, 1, 12",
    "BEGIN_OF_CYCLE, 2, 13"
  })
  void lockStepAppliesARequestKInstantsAfterTheNotificationsItWasDecidedOn(
      AdaptationPoint point, int latency, long firstEco) {
    List<String> modes = run(2, point, latency, 20);

    Worker reading = new Worker();
    reading.modes.addAll(modes);
    assertThat(reading.firstInstantIn("eco")).isEqualTo(firstEco);
  }

  @Test
  void lockStepRunsAreIdenticalWhateverTheNumberOfWorkers() {
    List<String> one = run(1, AdaptationPoint.END_OF_CYCLE, 1, 30);
    List<String> two = run(2, AdaptationPoint.END_OF_CYCLE, 1, 30);
    List<String> four = run(4, AdaptationPoint.END_OF_CYCLE, 1, 30);
    List<String> again = run(2, AdaptationPoint.END_OF_CYCLE, 1, 30);

    assertThat(one).hasSize(30).isEqualTo(two).isEqualTo(four).isEqualTo(again);
  }

  @Test
  void theMetaNeverRunsInsideTheBaseLevelsInstant() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    Worker program = new Worker();
    List<Boolean> insideInstant = new CopyOnWriteArrayList<>();
    List<Thread> metaThreads = new CopyOnWriteArrayList<>();
    BehavioralMeta meta =
        kernel.newBehavioralMeta(
            "meta",
            (context, n) -> {
              metaThreads.add(Thread.currentThread());
              insideInstant.add(program.reacting == Thread.currentThread());
            },
            Damping.none());
    robot(kernel, clock, meta, program, AdaptationPoint.END_OF_CYCLE, 1, Duration.ofSeconds(10));
    for (int i = 0; i < 20; i++) {
      clock.step();
    }
    drain(meta);

    assertThat(insideInstant).hasSizeGreaterThanOrEqualTo(20).containsOnly(false);
    assertThat(metaThreads).doesNotContain(Thread.currentThread());
  }

  @Test
  void aRefusedAdaptationIsAcknowledgedAsRefusedAndChangesNothing() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    Worker program = new Worker();
    program.refuseEco = true;
    BehavioralMeta meta =
        kernel.newBehavioralMeta("meta", ecoBelow(new AtomicBoolean()), Damping.none());
    Entity robot =
        robot(
            kernel, clock, meta, program, AdaptationPoint.END_OF_CYCLE, 1, Duration.ofSeconds(10));
    for (int i = 0; i < 20; i++) {
      clock.step();
    }
    drain(meta);
    clock.step(); // the acknowledgement, sent at instant 13, has been taken by now
    drain(meta);

    ModelView model = meta.model(robot).getValue();
    assertThat(model.requestedVersion()).isEqualTo(1);
    assertThat(model.appliedVersion()).isZero();
    assertThat(model.refusedAdaptations()).isEqualTo(1);
    assertThat(model.lastRefusal()).contains("no eco mode on this robot");
    assertThat(model.lockStep()).isTrue();
    assertThat(robot.appliedVersion()).isZero();
    assertThat(program.firstInstantIn("eco")).isZero();
  }

  @Test
  void aMetaThatStopsAnsweringLeavesTheBaseLevelRunningFree() throws InterruptedException {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    Worker program = new Worker();
    CountDownLatch release = new CountDownLatch(1);
    CountDownLatch stuck = new CountDownLatch(1);
    BehavioralMeta meta =
        kernel.newBehavioralMeta(
            "meta",
            (context, n) -> {
              if (n.seq() == 5) {
                stuck.countDown();
                release.await(); // the meta hangs from its fifth notification on
              }
            },
            Damping.none());
    Entity robot =
        robot(
            kernel, clock, meta, program, AdaptationPoint.END_OF_CYCLE, 1, Duration.ofMillis(200));
    try {
      for (int i = 0; i < 20; i++) {
        clock.step();
      }
      assertThat(stuck.await(5, TimeUnit.SECONDS)).isTrue();

      assertThat(program.modes).hasSize(20);
      assertThat(((EntityImpl<?>) robot).servant.lockStepTimeouts()).isEqualTo(1);
    } finally {
      release.countDown();
    }
  }

  @Test
  void aProgramNeedsASynchronousEntityAndLockStepAnAdaptationPointBetweenCycles() {
    assertThatThrownBy(() -> EntityOptions.defaults().withProgram(new Worker()))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("SYNCHRONOUS");
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    assertThatThrownBy(
            () ->
                EntityOptions.defaults()
                    .withConfig(ObjectConfig.synchronous(clock))
                    .withLockStep(1, Duration.ofSeconds(1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("ON_ARRIVAL");
    assertThatThrownBy(
            () ->
                EntityOptions.defaults()
                    .withConfig(ObjectConfig.synchronous(clock))
                    .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
                    .withLockStep(-1, Duration.ofSeconds(1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("-1");
  }

  @Test
  void stimuliGoToTheProgramNotToTheActivation() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    List<String> seen = new ArrayList<>();
    ReactiveProgram program =
        instant -> {
          for (Stimulus s : instant.stimuli()) {
            seen.add(s.trigger() + "=" + s.input());
          }
        };
    Entity robot =
        robotKind()
            .newEntity(
                "robot",
                kernel.basicBehavioralMeta(),
                EntityOptions.defaults()
                    .withConfig(ObjectConfig.synchronous(clock))
                    .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
                    .withProgram(program));
    clock.step();
    robot.send("work", 0.5);
    clock.step();

    assertThat(seen).containsExactly("work=0.5");
    assertThat(battery(robot)).isEqualTo(1.0);
  }
}
