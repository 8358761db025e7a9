package org.armgals.kernel;

import java.time.Duration;
import java.util.Map;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.representation.Behaviors;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PSpace;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;

/**
 * A runtime and a bootstrapped kernel per test, with a manual time source; and the battery robot of
 * the paper (§2.3) in the procedural representation.
 */
abstract class KernelFixture {
  ActiveRuntime runtime;
  Kernel kernel;
  final ManualTime time = new ManualTime();

  @BeforeEach
  void bootstrap() {
    runtime = ActiveRuntime.builder().workers(2).jmx(false).build();
    kernel =
        StructuralMeta.bootstrap(runtime, new KernelOptions(time, Duration.ofMillis(100), false));
  }

  @AfterEach
  void shutdown() {
    kernel.close();
    runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
  }

  static final PSpace ROBOT = PSpace.of(new PState(Map.of("battery", 1.0, "mode", "normal")));

  static Behaviors<PState> robotBehaviors() {
    return ROBOT.methods(
        PMethod.of(
            "work",
            (s, in) ->
                s.with("battery", round(Math.max(0, (double) s.get("battery") - (double) in)))),
        PMethod.of(
            "charge",
            (s, in) ->
                s.with("battery", round(Math.min(1, (double) s.get("battery") + (double) in)))),
        PMethod.of("eco", (s, in) -> s.with("mode", "eco")),
        PMethod.of("normal", (s, in) -> s.with("mode", "normal")),
        PMethod.returning(
            "ask", (s, in) -> new PMethod.Outcome(s, new Reflect(String.valueOf(in), null))),
        PMethod.of(
            "explode",
            (s, in) -> {
              throw new IllegalStateException("boom " + in);
            }));
  }

  /** Two decimals, so that replayed and observed batteries compare equal. */
  static double round(double v) {
    return Math.round(v * 100) / 100.0;
  }

  StructuralMeta<PState> robotKind() {
    return kernel.newStructuralMeta("Robot", ROBOT, robotBehaviors());
  }

  /**
   * Returns once {@code entity} has processed everything sent to it before: whatever it sent while
   * doing so has been sent.
   */
  static void drain(Entity entity) {
    ((EntityImpl<?>) entity).object().call(s -> Boolean.TRUE).getValue();
  }

  /** Alternates drains of the base entity and its meta, so that chains of reactions settle. */
  static void settle(Entity base, BehavioralMeta meta, int rounds) {
    for (int i = 0; i < rounds; i++) {
      drain(base);
      drain(meta);
    }
  }

  static double battery(Entity e) {
    return (double) e.state().observe().get("battery");
  }
}
