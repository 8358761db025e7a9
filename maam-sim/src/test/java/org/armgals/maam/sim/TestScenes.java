package org.armgals.maam.sim;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Consumer;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;

/** Scenes the tests share, and the way in to an atom's physics for the tests of the physics. */
final class TestScenes {

  private TestScenes() {}

  /**
   * Atom {@code id} of {@code s} in the physics' terms (leg targets as the joint's two angles): for
   * the tests of the physics; the public way to drive an atom is {@link Simulation#body}.
   */
  static BodyView atom(Simulation s, int id) {
    return ((SimulationImpl) s).view(id);
  }

  /** The atom behind a controller's {@code body}, in the physics' terms. */
  static BodyView joints(Body body) {
    return ((SimBody) body).atom;
  }

  /** Every atom's sensors, in id order, after each of {@code cycles} cycles of {@code s}. */
  static List<AtomSensors> sensorsEachCycle(Simulation s, int cycles) {
    List<AtomSensors> sensed = new ArrayList<>();
    for (int c = 0; c < cycles; c++) {
      s.runCycle();
      for (int id : s.atomIds()) {
        sensed.add(s.sensors(id));
      }
    }
    return sensed;
  }

  /** A crowd's run: its trace, and the contacts made between two atoms. */
  record CrowdRun(String trace, long atomContacts) {}

  /**
   * A crowd of {@code atoms} tripods {@code spacing} m apart on a grid, walking with seeded random
   * targets, on {@code threads}, atom 1 pushed after 10 cycles, 20 cycles; {@code setup} may switch
   * the simulation's ways of working before the first cycle.
   */
  static CrowdRun crowd(
      LegDynamics dynamics,
      int atoms,
      double spacing,
      int threads,
      Consumer<SimulationImpl> setup) {
    StringWriter out = new StringWriter();
    try (Simulation s =
        Simulation.builder(Scenes.grid(atoms, spacing))
            .legDynamics(dynamics)
            .threads(threads)
            .trace(out)
            .controllers(
                id -> {
                  SplittableRandom random = new SplittableRandom(id);
                  return (body, cycle) -> {
                    joints(body).setLegTarget(Leg.MZ, random.nextDouble(-0.4, 0.4), 0.2);
                    joints(body).setLegTarget(Leg.PX, random.nextDouble(-0.5, 0.5), 0);
                  };
                })
            .build()) {
      SimulationImpl impl = (SimulationImpl) s;
      setup.accept(impl);
      s.runCycles(10);
      s.push(1, new Vec3(2, 0, 0));
      s.runCycles(10);
      return new CrowdRun(out.toString(), impl.atomContacts());
    }
  }

  /** Two upright atoms in free space, +x of atom 1 facing -x of atom 2 across {@code gap} m. */
  static Scene facing(double gap, double turnDegrees, String extra) {
    double reach = AtomParams.defaults().reach();
    return Scenes.parse(
        "scene facing\ngravity 0 0 0\n"
            + extra
            + "atom 1 0 0 1\n"
            + "atom 2 "
            + (2 * reach + gap)
            + " 0 1 0 0 1 "
            + turnDegrees
            + "\n");
  }

  /** The pair of {@link #facing} bound at the start. */
  static Scene boundPair(String extra) {
    double reach = AtomParams.defaults().reach();
    return Scenes.parse(
        "scene bound\ngravity 0 0 0\n"
            + extra
            + "atom 1 0 0 1\natom 2 "
            + 2 * reach
            + " 0 1\nbond 1:+x 2:-x\n");
  }

  static double distance(Vec3 a, Vec3 b) {
    return Math.sqrt(
        (a.x() - b.x()) * (a.x() - b.x())
            + (a.y() - b.y()) * (a.y() - b.y())
            + (a.z() - b.z()) * (a.z() - b.z()));
  }
}
