package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.armgals.testkit.BrokerTest;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The contract of {@link Entity} run against both handles: the entity itself, in its runtime, and a
 * handle on it from another runtime ({@link Kernel#remoteEntity}), which must behave the same.
 */
class EntityHandleContractTest extends TwoRuntimesFixture {

  Entity handle(String which, Entity robot) {
    return switch (which) {
      case "local" -> robot;
      case "remote" -> metaKernel.remoteEntity("robot", robot.address(), metaRobots);
      default -> throw new IllegalArgumentException(which);
    };
  }

  @ParameterizedTest
  @ValueSource(strings = {"local", "remote"})
  void aHandleNamesItsEntityAndItsKind(String which) {
    Entity robot = robot("robot", NotificationPolicy.actionsOnly());
    Entity e = handle(which, robot);
    assertThat(e.name()).isEqualTo("robot");
    assertThat(e.address()).isEqualTo(robot.address());
    assertThat(e.structuralMeta().name()).isEqualTo("Robot");
    assertThat(e.isStopped()).isFalse();
    assertThat(e.notificationPolicy()).isEqualTo(NotificationPolicy.actionsOnly());
    assertThat(e.appliedVersion()).isZero();
  }

  @ParameterizedTest
  @ValueSource(strings = {"local", "remote"})
  void callsAndStimuliReachTheEntityInOrderAndItsStateIsSeen(String which) {
    Entity robot = robot("robot", NotificationPolicy.actionsOnly());
    Entity e = handle(which, robot);
    assertThat(e.call("work", 0.25).getValue(WAIT)).isNull();
    assertThat(e.state().observe()).containsEntry("battery", 0.75);
    e.send("charge", 0.1);
    e.call("eco", null).getValue(WAIT);
    assertThat(e.state()).isEqualTo(robot.state());
    assertThat(e.state().observe()).containsEntry("battery", 0.85).containsEntry("mode", "eco");
  }

  @BrokerTest(failOnObjectFailures = false) // fails on purpose
  @ParameterizedTest
  @ValueSource(strings = {"local", "remote"})
  void aCallOfAnUnknownBehaviorFailsNamingIt(String which) {
    Entity e = handle(which, robot("robot", NotificationPolicy.actionsOnly()));
    assertThatThrownBy(() -> e.call("fly", null).getValue(WAIT)).hasMessageContaining("fly");
  }
}
