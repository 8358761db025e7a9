package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.gals.Island;
import org.armgals.kernel.Adaptation;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.ModelView;
import org.armgals.kernel.Notification;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.ReflectionEvent;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A robot is a kernel entity and its meta a behavioral meta-entity (paper figure 8, §5.4): the
 * robot's cycle notifies the meta, which runs on its own object, never on the robot's thread,
 * models the robot from the notifications, and adapts it by versioned requests that name parts of
 * the kind's catalog, applied at the island's adaptation point and acknowledged, applied or
 * refused; in lock step exactly {@code k} cycles after the cycle they were decided on, whatever the
 * threads.
 */
class RobotAsKernelEntityTest {
  private final List<ReflectionEvent> heard = new CopyOnWriteArrayList<>();
  private final List<AutoCloseable> open = new ArrayList<>();

  /** A robot of the tests running as an entity, its meta, and the island that releases it. */
  private record Rig(
      TestRobot robot, Script meta, Island island, StructuralMeta<PState> kind, Kernel kernel) {

    /** One cycle with the sensors reading {@code wander} and {@code obstacle}; the motor. */
    int step(int wander, int obstacle) {
      robot.fake.set(TestRobot.WANDER, wander);
      robot.fake.set(TestRobot.OBSTACLE, obstacle);
      island.step();
      robot.time.now += TestRobot.PERIOD;
      return robot.fake.lastCommand(TestRobot.MOTOR).orElseThrow();
    }

    ModelView model() {
      return meta.model(robot).getValue();
    }
  }

  /** A meta that asks for the requests a script names, on the notification of their cycle. */
  static final class Script extends BMetaRobot {
    final Map<Long, List<Adaptation>> byCycle = new HashMap<>();
    final List<Boolean> onRobotsThread = new CopyOnWriteArrayList<>();
    final List<Long> seen = new CopyOnWriteArrayList<>();
    volatile TestRobot robot;

    Script(Damping damping) {
      super("bmrobot", damping);
    }

    Script at(long cycle, Adaptation request) {
      byCycle.computeIfAbsent(cycle, c -> new ArrayList<>()).add(request);
      return this;
    }

    @Override
    public void onNotification(MetaContext context, Notification n) {
      onRobotsThread.add(robot.inCycle());
      seen.add(n.seq());
      observation(n)
          .map(o -> (Long) o.get("cycle"))
          .map(byCycle::get)
          .ifPresent(requests -> requests.forEach(r -> context.adapt(n.entity(), r)));
    }
  }

  private Rig rig(int workers, AdaptationPoint point, int lockStep, Script meta) {
    ActiveRuntime runtime = ActiveRuntime.builder().workers(workers).jmx(false).build();
    open.add(() -> runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5)));
    Kernel kernel =
        org.armgals.kernel.StructuralMeta.bootstrap(
            runtime, KernelOptions.defaults().withJmx(false).withListener(heard::add));
    open.add(0, kernel);
    Island island = Island.builder("robots", runtime).adaptationPoint(point).jmx(false).build();
    open.add(0, island);
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering());
    StructuralMeta<PState> kind = kind(kernel, robot);
    meta.robot = robot;
    meta.start(kernel);
    robot.start(
        island,
        kind,
        meta,
        island
            .entityOptions()
            .withNotification(NotificationPolicy.statesOnly())
            .withLockStep(lockStep, Duration.ofSeconds(30)));
    return new Rig(robot, meta, island, kind, kernel);
  }

  static Schema wandering() {
    Sensing wander = new Sensing("wander", TestRobot.WANDER, 0);
    Drive motor = new Drive("motor", TestRobot.MOTOR);
    return Schema.builder("wander")
        .add(wander)
        .add(motor)
        .wire(wander, Sensing.OUT, motor, Drive.IN)
        .build();
  }

  /** The test robots' kind: its catalog has a wander module with a bias, and an avoid schema. */
  static StructuralMeta<PState> kind(Kernel kernel, TestRobot prototype) {
    return RobotKind.builder("TestRobot", TestRobot.class)
        .observing(prototype.observation())
        .module("wander", (r, p) -> new Sensing("wander", TestRobot.WANDER, (int) p.whole("bias")))
        .schema(
            "avoid",
            (r, p) ->
                Schema.builder("avoid").add(new Sensing("avoid", TestRobot.OBSTACLE, 100)).build())
        .connector(
            "avoid-inhibits-motor",
            (r, p) ->
                new Inhibitor(
                    new PortRef("avoid", Sensing.OUT),
                    new PortRef("motor", Drive.IN),
                    Duration.ZERO))
        .schema("tuned", (r, p) -> Schema.builder("tuned").add(new Tuned()).build())
        .define(kernel);
  }

  private static Adaptation biasFifty() {
    return RobotKind.changeModule("wander", Map.of("bias", 50));
  }

  @AfterEach
  void close() throws Exception {
    for (AutoCloseable c : open) {
      c.close();
    }
  }

  private static List<Integer> motor(Rig rig, int cycles) {
    List<Integer> commands = new ArrayList<>();
    for (int i = 0; i < cycles; i++) {
      commands.add(rig.step(5, 0));
    }
    return commands;
  }

  @ParameterizedTest(name = "{0}, latency {1}: the first cycle with the change is {2}")
  @CsvSource({
    "BEGIN_OF_CYCLE, 1, 4",
    "BEGIN_OF_CYCLE, 2, 5",
    "END_OF_CYCLE, 1, 5",
    "END_OF_CYCLE, 2, 6",
  })
  void aChangeDecidedOnCycleThreeIsAppliedKCyclesLater(
      AdaptationPoint point, int latency, int firstChanged) {
    Rig rig = rig(2, point, latency, new Script(Damping.none()).at(3, biasFifty()));
    List<Integer> commands = motor(rig, 9);

    // Decided on cycle 3: at the beginning of cycle 3 + k, or at the end of it (seen in the next).
    List<Integer> expected = new ArrayList<>();
    for (int cycle = 1; cycle <= 9; cycle++) {
      expected.add(cycle < firstChanged ? 5 : 55);
    }
    assertThat(commands).isEqualTo(expected);
  }

  @Test
  void lockStepRunsAreTheSameWhateverTheNumberOfWorkers() {
    List<List<Integer>> runs = new ArrayList<>();
    for (int workers : new int[] {1, 2, 4}) {
      heard.clear();
      Script script =
          new Script(Damping.none())
              .at(3, biasFifty())
              .at(7, RobotKind.addSchema("avoid", Map.of()))
              .at(8, RobotKind.addConnector("avoid-inhibits-motor", Map.of()));
      Rig rig = rig(workers, AdaptationPoint.BEGIN_OF_CYCLE, 1, script);
      List<Integer> commands = new ArrayList<>();
      for (int i = 0; i < 30; i++) {
        commands.add(rig.step(5, i % 3 == 0 ? 1 : 0));
      }
      runs.add(commands);
    }
    assertThat(runs.get(0)).hasSize(30).isEqualTo(runs.get(1)).isEqualTo(runs.get(2));
    assertThat(runs.get(0)).contains(55, -1);
  }

  @Test
  void theMetaModelsTheRobotFromItsNotificationsAndNeverRunsOnItsThread() {
    Rig rig =
        rig(2, AdaptationPoint.BEGIN_OF_CYCLE, 1, new Script(Damping.none()).at(3, biasFifty()));
    motor(rig, 8);
    rig.step(5, 0); // the acknowledgement of the change has been taken by now

    ModelView model = rig.model();
    assertThat(((PState) model.state()).fields())
        .containsEntry("cycle", 9L)
        .containsEntry("program", 2L)
        .containsEntry("schemas", List.of("wander"));
    assertThat(model.lastSeq()).isEqualTo(10); // the attachment's snapshot, then 9 cycles
    assertThat(model.requestedVersion()).isEqualTo(1);
    assertThat(model.appliedVersion()).isEqualTo(1);
    assertThat(model.lockStep()).isTrue();
    assertThat(rig.meta().onRobotsThread).hasSize(10).containsOnly(false);
    assertThat(rig.robot().appliedVersion()).isEqualTo(1);
    assertThat(rig.robot().behavioralMeta()).isPresent();
  }

  @Test
  void aRefusedRequestIsAcknowledgedAsRefusedWithItsReasonAndTheRobotRunsOn() {
    Script script =
        new Script(Damping.none())
            .at(2, RobotKind.changeModule("wander", Map.of("bias", "fifty")))
            .at(3, RobotKind.removeSchema("no-such-schema"))
            .at(4, RobotKind.addSchema("no-such-schema", Map.of()));
    Rig rig = rig(2, AdaptationPoint.BEGIN_OF_CYCLE, 1, script);
    assertThat(motor(rig, 8)).containsOnly(5);

    ModelView model = rig.model();
    assertThat(model.appliedVersion()).isZero();
    assertThat(model.refusedAdaptations()).isEqualTo(3);
    assertThat(model.lastRefusal())
        .contains("no schema 'no-such-schema' in its catalog")
        .contains("[avoid, tuned]");
    assertThat(refusals())
        .satisfiesExactly(
            r -> assertThat(r).contains("parameter 'bias' of module wander").contains("fifty"),
            r -> assertThat(r).contains("'no-such-schema'"),
            r -> assertThat(r).contains("no schema 'no-such-schema'"));
  }

  @Test
  void theRobotBuildsWhatARequestNamesFromItsKindsCatalog() {
    Script script =
        new Script(Damping.none())
            .at(2, RobotKind.setScheduling(List.of("avoid"), List.of()))
            .at(5, RobotKind.removeSchema("avoid"));
    Rig rig = rig(2, AdaptationPoint.BEGIN_OF_CYCLE, 1, script);
    rig.step(5, 0);
    rig.step(5, 0);
    rig.step(5, 0);

    assertThat(rig.robot().schedule().names()).containsExactly("avoid");
    rig.step(5, 0);
    rig.step(5, 0);
    rig.step(5, 0);
    assertThat(rig.robot().schedule().names()).isEmpty();
  }

  /** A perceptor whose bias its meta may set: emits the wander sensor plus its bias. */
  static final class Tuned implements Perceptor, Tunable {
    private int bias;

    @Override
    public String name() {
      return "tuned";
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(Sensing.OUT);
    }

    @Override
    public void perceive(org.armgals.maam.spi.Body body, Outputs out) {
      out.emit(Sensing.OUT, new Num(body.read(TestRobot.WANDER) + bias));
    }

    @Override
    public void tune(String parameter, Object value) {
      if (!parameter.equals("bias") || !(value instanceof Number n)) {
        throw new IllegalArgumentException(
            "tuned has a number parameter 'bias', not " + parameter + " = " + value);
      }
      bias = n.intValue();
    }
  }

  @Test
  void aParameterOfATunableModuleChangesWhileTheRobotRunsAndOfAnotherIsRefused() {
    Script script =
        new Script(Damping.none())
            .at(1, RobotKind.addSchema("tuned", Map.of()))
            .at(3, RobotKind.setParameter("tuned", "bias", 7))
            .at(4, RobotKind.setParameter("wander", "bias", 1))
            .at(5, RobotKind.setParameter("tuned", "gain", 2));
    Rig rig = rig(2, AdaptationPoint.BEGIN_OF_CYCLE, 1, script);
    PortRef tuned = new PortRef("tuned", Sensing.OUT);
    List<Integer> seen = new ArrayList<>();
    for (int i = 0; i < 7; i++) {
      rig.step(5, 0);
      rig.robot().emissions().stream()
          .filter(e -> e.port().equals(tuned))
          .forEach(e -> seen.add(((Num) e.signal()).value()));
    }

    // Added at the beginning of cycle 2, tuned at the beginning of cycle 4.
    assertThat(seen).containsExactly(5, 5, 12, 12, 12, 12);
    assertThat(refusals())
        .satisfiesExactly(
            r -> assertThat(r).contains("'wander' has no parameters to set (not Tunable)"),
            r -> assertThat(r).contains("not gain = 2"));
  }

  @Test
  void aSchemaTaughtToTheKindIsAskedForAndOneItForgetsLeavesEveryRobotOfIt() {
    Rig rig = rig(2, AdaptationPoint.BEGIN_OF_CYCLE, 1, new Script(Damping.none()));
    rig.step(5, 0);
    rig.kind()
        .addBehavior(
            RobotKind.schema(
                "brake",
                TestRobot.class,
                (r, p) ->
                    Schema.builder("brake")
                        .add(new Sensing("brake", TestRobot.OBSTACLE, (int) p.whole("by")))
                        .build()))
        .touch();
    rig.meta().adapt(rig.robot(), RobotKind.addSchema("brake", Map.of("by", 3))).getValue();
    rig.step(5, 0);
    rig.step(5, 0);
    assertThat(rig.robot().schedule().names()).contains("brake");

    rig.kind().deleteBehavior(RobotKind.schemaBehavior("brake")).touch();
    rig.step(5, 0); // takes the harmonization
    rig.step(5, 0); // begins without the schema
    assertThat(rig.robot().schedule().names()).doesNotContain("brake");
    assertThat(rig.robot().observation().fields()).containsEntry("schemas", List.of("wander"));
  }

  @Test
  void aRunningRobotIsNotSteppedByHandNorChangedButByRequests() {
    Rig rig = rig(1, AdaptationPoint.BEGIN_OF_CYCLE, 0, new Script(Damping.none()));

    assertThatThrownBy(rig.robot()::cycle)
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("kernel entity");
    assertThatThrownBy(() -> rig.robot().removeSchema("wander"))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("requests");
    assertThatThrownBy(
            () ->
                rig.robot()
                    .start(
                        rig.island(),
                        rig.kind(),
                        rig.kernel().basicBehavioralMeta(),
                        rig.island().entityOptions()))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("already runs");
    TestRobot idle = TestRobot.create();
    assertThatThrownBy(idle::state)
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("not started");
  }

  @Test
  void aFilterChangedWhileTheRobotRunsLosesAndDuplicatesNothing() {
    List<Long> handled = new CopyOnWriteArrayList<>();
    BMetaRobot meta =
        new BMetaRobot("bmrobot", Damping.none()) {
          @Override
          public void onNotification(MetaContext context, Notification n) {
            handled.add(n.seq());
            if (n instanceof org.armgals.kernel.ThresholdEvent) {
              context.setFilter(n.entity(), ""); // from now on, every cycle
            }
          }
        };
    ActiveRuntime runtime = ActiveRuntime.builder().workers(2).jmx(false).build();
    open.add(() -> runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5)));
    Kernel kernel =
        org.armgals.kernel.StructuralMeta.bootstrap(
            runtime, KernelOptions.defaults().withJmx(false).withListener(heard::add));
    open.add(0, kernel);
    Island island = Island.builder("robots", runtime).jmx(false).build();
    open.add(0, island);
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering());
    meta.start(kernel);
    robot.start(
        island,
        kind(kernel, robot),
        meta,
        island
            .entityOptions()
            .withNotification(
                NotificationPolicy.statesOnly()
                    .watching(new org.armgals.kernel.Threshold("late", "cycle", 5, 6)))
            .withLockStep(1, Duration.ofSeconds(30)));
    meta.setFilter(robot, "kind = 'threshold'").touch();
    island.step(20);
    meta.model(robot).getValue();

    List<Long> sent =
        heard.stream()
            .filter(e -> e instanceof ReflectionEvent.Notified n && n.entity().equals("test-robot"))
            .map(e -> ((ReflectionEvent.Notified) e).notification().seq())
            .toList();
    List<ReflectionEvent.Received> received =
        heard.stream()
            .filter(e -> e instanceof ReflectionEvent.Received r && r.entity().equals("test-robot"))
            .map(ReflectionEvent.Received.class::cast)
            .toList();
    // Every notification sent was received once, in order; the policy handled exactly those its
    // filter passed: the threshold event (cycle 7), then every state from there on.
    assertThat(sent)
        .isEqualTo(java.util.stream.LongStream.rangeClosed(1, sent.size()).boxed().toList());
    assertThat(received).extracting(r -> r.notification().seq()).isEqualTo(sent);
    assertThat(handled)
        .isEqualTo(
            received.stream()
                .filter(ReflectionEvent.Received::passed)
                .map(r -> r.notification().seq())
                .toList());
    ReflectionEvent.Received threshold =
        received.stream()
            .filter(r -> r.notification() instanceof org.armgals.kernel.ThresholdEvent)
            .findFirst()
            .orElseThrow();
    assertThat(received)
        .allMatch(r -> r.passed() == (r.notification().seq() >= threshold.notification().seq()));
    assertThat(handled).hasSizeGreaterThan(10);
  }

  @Test
  void theRobotAndItsMetaShowInJmxAsEveryKernelEntity() throws Exception {
    ActiveRuntime runtime =
        ActiveRuntime.builder().name("jmx-robots").workers(1).jmx(false).build();
    open.add(() -> runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5)));
    Kernel kernel = org.armgals.kernel.StructuralMeta.bootstrap(runtime);
    open.add(0, kernel);
    Island island = Island.builder("robots", runtime).jmx(false).build();
    open.add(0, island);
    TestRobot robot = TestRobot.create();
    robot.addSchema(wandering());
    Script meta = new Script(Damping.none()).at(2, biasFifty());
    meta.robot = robot;
    meta.start(kernel);
    robot.start(
        island,
        kind(kernel, robot),
        meta,
        island
            .entityOptions()
            .withNotification(NotificationPolicy.statesOnly())
            .withLockStep(1, Duration.ofSeconds(30)));
    robot.fake.set(TestRobot.WANDER, 5);
    robot.fake.set(TestRobot.OBSTACLE, 0);
    island.step(4);

    javax.management.MBeanServer server =
        java.lang.management.ManagementFactory.getPlatformMBeanServer();
    javax.management.ObjectName entity =
        new javax.management.ObjectName(
            "org.armgals.kernel:type=Entity,runtime=\"jmx-robots\",name=\"test-robot\"");
    javax.management.ObjectName metaBean =
        new javax.management.ObjectName(
            "org.armgals.kernel:type=BehavioralMeta,runtime=\"jmx-robots\",name=\"bmrobot\"");
    assertThat(server.getAttribute(entity, "BehavioralMeta")).isEqualTo("bmrobot");
    assertThat((String) server.getAttribute(entity, "State")).contains("cycle=4");
    assertThat(server.getAttribute(entity, "AppliedVersion")).isEqualTo(1L);
    assertThat((String[]) server.getAttribute(entity, "Behaviors"))
        .contains("cycle", "changeModule", "module:wander", "schema:avoid");
    assertThat(server.getAttribute(metaBean, "AppliedVersions"))
        .isInstanceOfSatisfying(
            javax.management.openmbean.TabularData.class,
            t -> assertThat(t.toString()).contains("test-robot"));
  }

  private List<String> refusals() {
    return heard.stream()
        .filter(e -> e instanceof ReflectionEvent.Applied a && !a.applied())
        .map(e -> ((ReflectionEvent.Applied) e).refusal())
        .toList();
  }
}
