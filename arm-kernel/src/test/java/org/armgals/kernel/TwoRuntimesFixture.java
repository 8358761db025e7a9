package org.armgals.kernel;

import java.time.Duration;
import java.util.function.Predicate;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.jms.JmsTransport;
import org.armgals.representation.p.PState;
import org.armgals.testkit.BrokerTest;
import org.armgals.testkit.TestBroker;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;

/**
 * Two runtimes on one embedded Artemis broker (the testkit's, one per class), each with its own JMS
 * transport and kernel, and the battery robot's kind known to both (decision 0024); a fresh topic
 * prefix per test. The testkit closes the runtimes and transports after each test.
 */
@BrokerTest
abstract class TwoRuntimesFixture {
  static final Duration WAIT = Duration.ofSeconds(10);

  TestBroker broker;

  JmsTransport baseTransport;
  JmsTransport metaTransport;
  ActiveRuntime baseRuntime;
  ActiveRuntime metaRuntime;
  Kernel baseKernel;
  Kernel metaKernel;
  StructuralMeta<PState> baseRobots;
  StructuralMeta<PState> metaRobots;
  final ManualTime time = new ManualTime();

  @BeforeEach
  void twoRuntimes(TestBroker broker) {
    this.broker = broker;
    baseTransport = broker.transport(Kernel::allowKernelEvents);
    metaTransport = broker.transport(Kernel::allowKernelEvents);
    baseRuntime = broker.runtime("base", baseTransport);
    metaRuntime = broker.runtime("meta", metaTransport);
    KernelOptions options = new KernelOptions(time, Duration.ofMillis(100), false);
    baseKernel = StructuralMeta.bootstrap(baseRuntime, options);
    metaKernel = StructuralMeta.bootstrap(metaRuntime, options);
    // Behaviors are code: both sides know the kind (decision 0024).
    baseRobots =
        baseKernel.newStructuralMeta("Robot", KernelFixture.ROBOT, KernelFixture.robotBehaviors());
    metaRobots =
        metaKernel.newStructuralMeta("Robot", KernelFixture.ROBOT, KernelFixture.robotBehaviors());
  }

  @AfterEach
  void closeKernels() {
    baseKernel.close();
    metaKernel.close();
  }

  /** A robot of the base runtime, registered in the name service, as the meta runtime finds it. */
  Entity robot(String name, NotificationPolicy policy) {
    Entity robot =
        baseRobots.newEntity(
            name,
            baseKernel.basicBehavioralMeta(),
            EntityOptions.defaults().withNotification(policy));
    baseTransport.register(name, robot.address());
    return robot;
  }

  /** Returns once the meta's model of {@code entity} satisfies {@code p}: its objects' guard. */
  static ModelView awaitModel(BehavioralMeta meta, Entity entity, Predicate<ModelView> p) {
    BehavioralMetaImpl m = (BehavioralMetaImpl) meta;
    Address a = entity.address();
    m.object()
        .callWhen(
            s -> {
              BehavioralMetaImpl.Published published = m.views.get(a);
              return published != null && p.test(published.view());
            },
            s -> Boolean.TRUE)
        .getValue(WAIT);
    return meta.model(entity).getValue(WAIT);
  }

  /**
   * Returns once a reactive {@code base} has an event waiting for its next release (an attachment
   * that crossed the broker, say): a reactive object takes its events only at its releases, so a
   * test must not step its clock before what it sent has arrived.
   */
  static void awaitQueued(Entity base) {
    long deadline = System.nanoTime() + WAIT.toNanos();
    while (((EntityImpl<?>) base).object().queueDepth() == 0) {
      if (System.nanoTime() > deadline) {
        throw new AssertionError(base + " received nothing within " + WAIT);
      }
      java.util.concurrent.locks.LockSupport.parkNanos(1_000_000L);
    }
  }

  /** Returns once the base entity has applied the adaptation {@code version}. */
  static void awaitApplied(Entity base, long version) {
    ((EntityImpl<?>) base)
        .object()
        .callWhen(s -> s.appliedVersion() >= version, s -> Boolean.TRUE)
        .getValue(WAIT);
  }

  /** Returns once {@code base} has (or has lost) the behavior {@code name}. */
  static void awaitBehavior(Entity base, String name, boolean present) {
    ((EntityImpl<?>) base)
        .object()
        .callWhen(s -> s.behaviors().lookup(name).isPresent() == present, s -> Boolean.TRUE)
        .getValue(WAIT);
  }
}
