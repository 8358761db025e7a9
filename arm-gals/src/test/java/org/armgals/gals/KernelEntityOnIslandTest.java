package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PSpace;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Kernel entities in the synchronous mode: reactive entities of the ARM (paper figure 8). */
class KernelEntityOnIslandTest {
  private final ActiveRuntime runtime = Fixtures.runtime("kernel", 2);
  private final Kernel kernel =
      StructuralMeta.bootstrap(
          runtime, new KernelOptions(new FakeTime(), Duration.ofMillis(100), false));
  private final Island island =
      Island.builder("island", runtime).period(Duration.ofMillis(10)).build();

  @AfterEach
  void close() {
    island.close();
    kernel.close();
    runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
  }

  private static final PSpace BATTERY = PSpace.of(new PState(Map.of("battery", 100)));

  private StructuralMeta<PState> robotKind() {
    return kernel.newStructuralMeta(
        "Robot",
        BATTERY,
        BATTERY.methods(
            PMethod.of("work", (s, in) -> s.with("battery", (int) s.get("battery") - (int) in))));
  }

  private Entity robot(StructuralMeta<PState> kind) {
    return island.spawn(kind, "robot", kernel.basicBehavioralMeta(), NotificationPolicy.quiet());
  }

  @Test
  void kernelEntityTakesTheStimuliOfAReactionAtTheIslandsNextRelease() {
    Entity robot = robot(robotKind());
    island.spawn("driver", 0, c -> robot.send("work", 10));
    List<Object> batteries = new ArrayList<>();
    for (int k = 0; k < 3; k++) {
      island.step();
      batteries.add(((PState) robot.state()).get("battery")); // read between instants
    }

    // the driver sends at each instant; the robot takes it at the next release
    assertThat(batteries).containsExactly(100, 90, 80);
  }

  @Test
  void kernelEntityStimulusFromOutsideWaitsForTheNextRelease() {
    Entity robot = robot(robotKind());
    robot.send("work", 5);
    assertThat(((PState) robot.state()).get("battery")).isEqualTo(100);
    island.step();
    assertThat(((PState) robot.state()).get("battery")).isEqualTo(95);
  }

  @Test
  void kernelRefusesATakenName() {
    StructuralMeta<PState> kind = robotKind();
    robot(kind);
    assertThatThrownBy(() -> robot(kind)).isInstanceOf(IllegalArgumentException.class);
  }

  @Test
  void islandAdaptsOnlyBetweenInstants() {
    assertThatThrownBy(
            () -> Island.builder("i", runtime).adaptationPoint(AdaptationPoint.ON_ARRIVAL))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage(
            "adaptation point of an island must be BEGIN_OF_CYCLE or END_OF_CYCLE, was ON_ARRIVAL");
  }
}
