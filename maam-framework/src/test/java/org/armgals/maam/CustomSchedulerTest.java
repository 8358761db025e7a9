package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A custom {@link Scheduler} is held to {@link Schedule}'s contract when the program changes: a
 * schedule that misses, repeats or invents a module, or runs a consumer before its producer, is
 * refused naming what is wrong, and the program stays as it was.
 */
class CustomSchedulerTest {

  private final WanderAndAvoid p = new WanderAndAvoid();

  /** The built-in order, then changed by {@code change}. */
  private static Scheduler reordering(
      java.util.function.UnaryOperator<List<BehaviorModule>> change) {
    return new Scheduler() {
      @Override
      public Schedule schedule(List<Schema> schemas, List<Connector> connectors) {
        List<BehaviorModule> order =
            new ArrayList<>(Scheduler.topological().schedule(schemas, connectors).modules());
        return new Schedule(change.apply(order));
      }

      @Override
      public String toString() {
        return "reordering";
      }
    };
  }

  @Test
  void aConsumerScheduledBeforeItsProducerIsRefusedNamingBothAndTheWire() {
    MetaRobotImpl meta = new MetaRobotImpl(reordering(order -> order.reversed()));
    assertThatThrownBy(() -> meta.apply(new ProgramChange.AddSchema(p.wandering)))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("scheduler reordering returned [motor, wander]")
        .hasMessageContaining(
            "'motor' runs before 'wander', against the wire wander.out -> motor.in")
        .hasMessageContaining("producers before consumers");
    assertThat(meta.version()).isZero();
    assertThat(meta.schemas()).isEmpty();
    assertThat(meta.schedule().modules()).isEmpty();
  }

  @Test
  void aConnectorsTargetBeforeItsSourceIsRefused() {
    // avoid, wander, motor → wander, motor, avoid: the wire holds, the inhibitor does not.
    MetaRobotImpl meta =
        new MetaRobotImpl(
            reordering(
                order -> {
                  Collections.rotate(order, -1);
                  return order;
                }));
    assertThatThrownBy(
            () ->
                meta.apply(
                    new ProgramChange.SetScheduling(
                        List.of(p.avoiding, p.wandering), List.of(p.avoidInhibitsMotor))))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("'motor' runs before 'avoid', against the connector");
    assertThat(meta.version()).isZero();
  }

  @Test
  void aScheduleMissingRepeatingOrInventingAModuleOrNoneIsRefused() {
    ProgramChange.AddSchema add = new ProgramChange.AddSchema(p.wandering);
    assertThatThrownBy(() -> new MetaRobotImpl(reordering(order -> order.subList(0, 1))).apply(add))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("modules [motor] are not scheduled");
    assertThatThrownBy(
            () ->
                new MetaRobotImpl(reordering(order -> List.of(p.wander, p.wander, p.motor)))
                    .apply(add))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("module 'wander' is scheduled twice");
    assertThatThrownBy(() -> new MetaRobotImpl((schemas, connectors) -> null).apply(add))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("returned null");
    Drive impostor = new Drive("motor", TestRobot.OTHER_MOTOR);
    assertThatThrownBy(
            () -> new MetaRobotImpl(reordering(order -> List.of(p.wander, impostor))).apply(add))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("module 'motor' is not one of the program's");
  }

  @Test
  void anotherOrderThatKeepsTheContractIsUsed() {
    // The two schemas are independent until the inhibitor: wander's first is as valid.
    MetaRobotImpl meta =
        new MetaRobotImpl(reordering(order -> List.of(p.wander, p.motor, p.avoid)));
    meta.apply(new ProgramChange.SetScheduling(List.of(p.avoiding, p.wandering), List.of()));
    assertThat(meta.schedule().names()).containsExactly("wander", "motor", "avoid");
    assertThat(meta.version()).isEqualTo(1);
  }
}
