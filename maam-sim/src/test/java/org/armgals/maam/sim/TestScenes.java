package org.armgals.maam.sim;

/** Scenes the tests share. */
final class TestScenes {

  private TestScenes() {}

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
