package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.ConcurrentHashMap;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.BindCommand;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.NeighbourMessage;
import org.junit.jupiter.api.Test;

/**
 * Confined controllers run on the lanes at once (decision 0077), and the run is the one the calling
 * thread alone gives, bit for bit, with messages, lost messages, unbinds and binds.
 */
class ConfinedControllersTest {

  /** {@code pairs} pairs of atoms bound +x to -x, in free space, a metre apart. */
  private static Scene boundPairs(int pairs) {
    double reach = AtomParams.defaults().reach();
    List<Scene.Placement> atoms = new ArrayList<>();
    List<Scene.Bond> bonds = new ArrayList<>();
    for (int p = 0; p < pairs; p++) {
      double x = (p % 12) * 1.0;
      double y = (p / 12) * 1.0;
      atoms.add(new Scene.Placement(2 * p + 1, new Vec3(x, y, 1), Quat.ofAxisAngle(0, 0, 1, 0)));
      atoms.add(
          new Scene.Placement(
              2 * p + 2, new Vec3(x + 2 * reach, y, 1), Quat.ofAxisAngle(0, 0, 1, 0)));
      bonds.add(new Scene.Bond(2 * p + 1, Leg.PX, 2 * p + 2, Leg.MX));
    }
    Scene base = TestScenes.boundPair("");
    return new Scene("pairs", base.params(), base.gravity(), List.of(), atoms, bonds);
  }

  /**
   * Each atom swings a leg, sends through its bound leg every cycle, and every fifth atom lets go
   * at cycle 6 and locks again at cycle 9, confined or not; the threads the controllers ran on go
   * to {@code threads}.
   */
  private static Controller walker(int id, boolean confined, Set<Thread> threads) {
    SplittableRandom random = new SplittableRandom(id);
    Leg bound = id % 2 == 1 ? Leg.PX : Leg.MX;
    Controller c =
        (body, cycle) -> {
          threads.add(Thread.currentThread());
          body.command(Atom.target(Leg.PZ), LegAngles.swing(random.nextDouble(0, 0.4), 0.5));
          body.command(Atom.SEND, new NeighbourMessage(bound, id + "@" + cycle));
          if (id % 5 == 0 && cycle == 6) {
            body.command(Atom.bind(bound), BindCommand.UNBIND);
            body.command(Atom.SEND, new NeighbourMessage(bound, "after"));
          }
          if (id % 5 == 0 && cycle == 9) {
            body.command(Atom.bind(bound), BindCommand.BIND);
          }
        };
    return confined ? Controller.confined(c) : c;
  }

  private static String run(int threads, boolean confined, Set<Thread> ranOn) {
    StringWriter out = new StringWriter();
    try (Simulation s =
        Simulation.builder(boundPairs(Lanes.MIN_PER_LANE))
            .threads(threads)
            .packetLoss(0.3)
            .trace(out)
            .controllers(id -> walker(id, confined, ranOn))
            .build()) {
      s.runCycles(12);
    }
    return out.toString();
  }

  @Test
  void confinedControllersOnTwoLanesRunBitForBitAsOnOneThread() {
    Set<Thread> lanes = ConcurrentHashMap.newKeySet();
    String two = run(2, true, lanes);
    String one = run(1, false, ConcurrentHashMap.newKeySet());
    assertThat(lanes).hasSize(2);
    assertThat(two).contains("\"type\":\"unbound\"", "\"type\":\"messageLost\"").isEqualTo(one);
  }

  @Test
  void oneControllerNotConfinedKeepsThemAllOnTheSimulationsThread() {
    Set<Thread> threads = ConcurrentHashMap.newKeySet();
    try (Simulation s =
        Simulation.builder(boundPairs(Lanes.MIN_PER_LANE))
            .threads(2)
            .controllers(id -> walker(id, true, threads))
            .build()) {
      s.setController(7, walker(7, false, threads));
      s.runCycles(2);
      assertThat(threads).containsExactly(Thread.currentThread());
      s.setController(7, walker(7, true, threads));
      s.runCycles(2);
      assertThat(threads).hasSize(2);
    }
  }

  @Test
  void aBodyDrivenFromALaneBindsOnlyAfterThePass() {
    try (Simulation s =
        Simulation.builder(boundPairs(Lanes.MIN_PER_LANE))
            .threads(2)
            .controllers(
                id ->
                    Controller.confined(
                        (body, cycle) -> {
                          if (cycle == 1) {
                            joints(body).unbind(id % 2 == 1 ? Leg.PX : Leg.MX);
                            // Still bound while the pass runs: the unbind waits for its end.
                            assertThat(
                                    joints(body).model.leg(id % 2 == 1 ? Leg.PX : Leg.MX).binding)
                                .isNotNull();
                          }
                        }))
            .build()) {
      s.runCycles(2);
      assertThat(s.lastEvents()).hasSize(Lanes.MIN_PER_LANE);
      assertThat(TestScenes.atom(s, 1).model.leg(Leg.PX).binding).isNull();
    }
  }
}
