package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.armgals.active.ShutdownMode;
import org.armgals.active.TimeSource;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.kernel.spi.ReactiveProgram;
import org.armgals.representation.Behaviors;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The reflective loop as the kernel tells it ({@link ReflectionEvent}): both sides of every step,
 * with the instant or the cause that places it on one time line; and what the loop needs to stay
 * exact and reproducible: duplicates reach the policy once, a lock-step meta may decide at the end
 * of an instant, an adaptation's time is measured against the cycle's budget, and a program hears
 * its kind change. ({@link LockStepAcrossRuntimesTest} has the loop across runtimes.)
 */
class ReflectiveLoopTest {
  private final ManualTime time = new ManualTime();
  private final List<ReflectionEvent> heard = new CopyOnWriteArrayList<>();
  private final ActiveRuntime runtime = ActiveRuntime.builder().workers(2).jmx(false).build();
  private Kernel kernel = kernel(TimeSource.system());

  private Kernel kernel(TimeSource stopwatch) {
    return StructuralMeta.bootstrap(
        runtime,
        new KernelOptions(time, Duration.ofMillis(100), false)
            .withListener(heard::add)
            .withStopwatch(stopwatch));
  }

  @AfterEach
  void shutdown() {
    kernel.close();
    runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
  }

  private Entity robot(
      ManualClock clock, BehavioralMeta meta, ReactiveProgram program, int lockStep) {
    return kernel
        .newStructuralMeta("Robot", KernelFixture.ROBOT, KernelFixture.robotBehaviors())
        .newEntity(
            "robot",
            meta,
            EntityOptions.defaults()
                .withConfig(ObjectConfig.synchronous(clock))
                .withNotification(NotificationPolicy.statesOnly())
                .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
                .withProgram(program)
                .withLockStep(lockStep, Duration.ofSeconds(60)));
  }

  /** Steps {@code clock} {@code n} times, the kernel's time 10 ms ahead at each instant. */
  private void step(ManualClock clock, int n) {
    for (int i = 0; i < n; i++) {
      time.advance(Duration.ofMillis(10));
      clock.step();
    }
  }

  @Test
  void theListenerHearsBothSidesOfTheLoopEachPlacedByInstantOrCause() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    BehavioralMeta meta =
        kernel.newBehavioralMeta(
            "meta",
            (context, n) -> {
              if (n instanceof StateEvent s && s.observation().get("battery") instanceof Double b) {
                if (b < 0.975 && context.model(s.entity()).requestedVersion() == 0) {
                  context.setFilter(s.entity(), "kind = 'threshold'");
                  context.adapt(s.entity(), new Adaptation.ApplyBehavior("eco", null));
                }
              }
            },
            Damping.none());
    Entity robot = robot(clock, meta, new ReactiveProgramTest.Worker(), 1);
    step(clock, 6);
    KernelFixture.drain(meta);

    // The kernel's own entities notify basicBehavioralMeta too; the robot: its snapshot at
    // attachment, then one state event per instant (battery 0.99 at instant 1, 0.98 at 2...).
    List<ReflectionEvent.Notified> notified =
        only(ReflectionEvent.Notified.class).stream()
            .filter(n -> n.entity().equals("robot"))
            .toList();
    ReflectionEvent.Notified third =
        notified.stream()
            .filter(n -> n.notification() instanceof StateEvent s && "work".equals(s.behavior()))
            .skip(2)
            .findFirst()
            .orElseThrow();
    assertThat(third.instant()).isEqualTo(3);
    assertThat(third.notification().nanoTime()).isEqualTo(time0() + 30_000_000L);

    List<ReflectionEvent.Received> received =
        only(ReflectionEvent.Received.class).stream()
            .filter(r -> r.entity().equals("robot"))
            .toList();
    assertThat(received).extracting(ReflectionEvent.Received::meta).containsOnly("meta");
    long decidedOn = third.notification().seq();
    assertThat(received)
        .filteredOn(r -> r.notification().seq() <= decidedOn)
        .allMatch(ReflectionEvent.Received::passed);
    assertThat(received)
        .filteredOn(r -> r.notification().seq() > decidedOn)
        .isNotEmpty()
        .noneMatch(ReflectionEvent.Received::passed); // the new filter takes thresholds only

    ReflectionEvent.Cause cause =
        new ReflectionEvent.Cause("robot", decidedOn, time0() + 30_000_000L);
    assertThat(only(ReflectionEvent.FilterChanged.class))
        .containsExactly(
            new ReflectionEvent.FilterChanged("meta", "robot", "kind = 'threshold'", cause));
    ReflectionEvent.Requested requested = only(ReflectionEvent.Requested.class).get(0);
    assertThat(requested.cause()).isEqualTo(cause);
    assertThat(requested.held()).isTrue();
    assertThat(requested.request().version()).isEqualTo(1);
    // Decided on instant 3, applied at the end of instant 3 + k = 4.
    ReflectionEvent.Applied applied = only(ReflectionEvent.Applied.class).get(0);
    assertThat(applied.instant()).isEqualTo(4);
    assertThat(applied.applied()).isTrue();
    assertThat(applied.request()).isEqualTo(requested.request());
    assertThat(robot.appliedVersion()).isEqualTo(1);
  }

  @Test
  void aRefusalIsHeardWithItsReason() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    ReactiveProgramTest.Worker program = new ReactiveProgramTest.Worker();
    program.refuseEco = true;
    BehavioralMeta meta =
        kernel.newBehavioralMeta(
            "meta", ReactiveProgramTest.ecoBelow(new AtomicBoolean()), Damping.none());
    robot(clock, meta, program, 1);
    step(clock, 14);

    assertThat(only(ReflectionEvent.Applied.class))
        .singleElement()
        .satisfies(
            a -> {
              assertThat(a.applied()).isFalse();
              assertThat(a.refusal()).contains("no eco mode on this robot");
              assertThat(a.instant()).isEqualTo(12);
            });
  }

  @Test
  void theDampingHeldBackIsHeardAsSuppressed() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    BehavioralMeta meta =
        kernel.newBehavioralMeta(
            "meta",
            (context, n) -> context.adapt(n.entity(), new Adaptation.ApplyBehavior("eco", null)),
            new Damping(Duration.ofSeconds(1), 10, Duration.ofSeconds(10)));
    robot(clock, meta, new ReactiveProgramTest.Worker(), 1);
    step(clock, 5);
    KernelFixture.drain(meta);

    assertThat(only(ReflectionEvent.Requested.class)).hasSize(1);
    assertThat(only(ReflectionEvent.Suppressed.class))
        .hasSizeGreaterThanOrEqualTo(4)
        .allMatch(s -> s.cause() != null && s.adaptation() instanceof Adaptation.ApplyBehavior);
  }

  @Test
  void aDuplicatedNotificationReachesThePolicyOnce() {
    List<Long> seen = new CopyOnWriteArrayList<>();
    BehavioralMeta meta =
        kernel.newBehavioralMeta("meta", (context, n) -> seen.add(n.seq()), Damping.none());
    Entity robot =
        kernel
            .newStructuralMeta("Robot", KernelFixture.ROBOT, KernelFixture.robotBehaviors())
            .newEntity("robot", meta);
    robot.call("work", 0.1).getValue();
    KernelFixture.drain(meta);
    StateEvent again =
        new StateEvent(
            robot.address(),
            meta.address(),
            3,
            time.nanoTime(),
            "work",
            robot.state().observe(),
            true);
    runtime.ref(meta.address()).send(again); // delivered twice, as at-least-once may
    KernelFixture.drain(meta);

    assertThat(seen).containsExactly(1L, 2L, 3L);
  }

  @Test
  void aLockStepMetaMayDecideAtTheEndOfAnInstantForTheAdaptationPointKLater() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    ReactiveProgramTest.Worker program = new ReactiveProgramTest.Worker();
    List<Long> ends = new CopyOnWriteArrayList<>();
    MetaPolicy atInstant7 =
        new MetaPolicy() {
          @Override
          public void onNotification(MetaContext context, Notification notification) {}

          @Override
          public void onInstant(MetaContext context, Address entity, long instant) {
            ends.add(instant);
            if (instant == 7) {
              context.adapt(entity, new Adaptation.ApplyBehavior("eco", null));
            }
          }
        };
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", atInstant7, Damping.none());
    robot(clock, meta, program, 2);
    step(clock, 12);

    // The barrier sent at attachment closes instant 0 (nothing before the first release).
    assertThat(ends).startsWith(0L, 1L, 2L, 3L, 4L, 5L, 6L, 7L, 8L);
    // Decided at the end of instant 7, applied at the end of instant 9: instant 10 runs in eco.
    assertThat(program.firstInstantIn("eco")).isEqualTo(10);
    assertThat(only(ReflectionEvent.Requested.class).get(0).cause())
        .extracting(ReflectionEvent.Cause::nanoTime)
        .isEqualTo(time0() + 70_000_000L);
  }

  @Test
  void anAdaptationPointLongerThanTheCycleIsCountedAsAnOverrun() {
    kernel.close();
    AtomicLong watch = new AtomicLong();
    kernel = kernel(() -> watch.addAndGet(6_000_000L)); // each reading 6 ms after the last
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    AtomicBoolean sent = new AtomicBoolean();
    BehavioralMeta meta =
        kernel.newBehavioralMeta(
            "meta",
            (context, n) -> {
              if (n.seq() == 2 && sent.compareAndSet(false, true)) {
                context.adapt(n.entity(), new Adaptation.ApplyBehavior("eco", null));
                context.adapt(n.entity(), new Adaptation.ApplyBehavior("charge", 0.5));
              }
            },
            Damping.none());
    Entity robot = robot(clock, meta, new ReactiveProgramTest.Worker(), 1);
    step(clock, 4);

    List<ReflectionEvent.Applied> applied = only(ReflectionEvent.Applied.class);
    assertThat(applied)
        .extracting(ReflectionEvent.Applied::nanos)
        .containsExactly(6_000_000L, 6_000_000L);
    // 6 ms into a 10 ms cycle the first fits; at 12 ms the second does not.
    assertThat(applied).extracting(ReflectionEvent.Applied::overrun).containsExactly(false, true);
    EntityServant<?> servant = ((EntityImpl<?>) robot).servant;
    assertThat(servant.adaptationOverruns()).isEqualTo(1);
    assertThat(servant.adaptationMaxNanos()).isEqualTo(12_000_000L);
  }

  @Test
  void aProgramHearsItsKindTaughtAndForgettingBehaviors() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    List<List<String>> told = new CopyOnWriteArrayList<>();
    ReactiveProgram program =
        new ReactiveProgram() {
          @Override
          public void react(org.armgals.kernel.spi.InstantContext instant) {}

          @Override
          public void harmonized(Behaviors<?> behaviors) {
            told.add(List.copyOf(behaviors.names()));
          }
        };
    StructuralMeta<PState> kind =
        kernel.newStructuralMeta("Robot", KernelFixture.ROBOT, KernelFixture.robotBehaviors());
    kind.newEntity(
        "robot",
        kernel.basicBehavioralMeta(),
        EntityOptions.defaults()
            .withConfig(ObjectConfig.synchronous(clock))
            .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
            .withProgram(program));
    clock.step();
    kind.addBehavior(PMethod.of("sleep", (s, in) -> s)).touch();
    clock.step();
    kind.deleteBehavior("charge").touch();
    clock.step();

    assertThat(told).hasSize(2);
    assertThat(told.get(0)).contains("sleep", "charge");
    assertThat(told.get(1)).contains("sleep").doesNotContain("charge");
  }

  private long time0() {
    return 1_000_000_000L;
  }

  private <T extends ReflectionEvent> List<T> only(Class<T> type) {
    return heard.stream().filter(type::isInstance).map(type::cast).toList();
  }
}
