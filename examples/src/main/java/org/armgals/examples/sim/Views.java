package org.armgals.examples.sim;

import java.util.ArrayList;
import java.util.List;
import org.armgals.examples.plot.AtomView;
import org.armgals.examples.plot.SceneView;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.Obstacle;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Vec3;
import org.armgals.maam.spi.Leg;

/**
 * Atoms as the pictures draw them, from their sensor readings: the kernel where it is, each leg
 * from the kernel to its tip, where the simulator has it ({@link AtomSensors#tip}), bound or not.
 *
 * <p>A scene's obstacles as the pictures draw them: a box as a block between its corners, a pipe as
 * a tube whose outer radius is its inner radius plus its wall (its 16 staves drawn round).
 */
final class Views {
  private Views() {}

  static AtomView of(AtomSensors atom, AtomParams params) {
    List<AtomView.Leg> legs = new ArrayList<>(6);
    for (Leg leg : Leg.values()) {
      legs.add(new AtomView.Leg(vec(atom.tip(leg, params)), atom.leg(leg).neighbour().isPresent()));
    }
    return new AtomView(
        String.valueOf(atom.id()), vec(atom.position()), params.kernelRadius(), legs);
  }

  static SceneView of(Scene scene) {
    List<SceneView.Solid> solids = new ArrayList<>();
    for (Obstacle obstacle : scene.obstacles()) {
      solids.add(
          switch (obstacle) {
            case Obstacle.Box box -> {
              Vec3 c = box.center();
              Vec3 s = box.size();
              yield new SceneView.Block(
                  new AtomView.Vec(c.x() - s.x() / 2, c.y() - s.y() / 2, c.z() - s.z() / 2),
                  new AtomView.Vec(c.x() + s.x() / 2, c.y() + s.y() / 2, c.z() + s.z() / 2));
            }
            case Obstacle.Pipe pipe ->
                new SceneView.Tube(
                    vec(pipe.center()),
                    pipe.axis() - 'x',
                    pipe.innerRadius(),
                    pipe.innerRadius() + pipe.wall(),
                    pipe.length());
          });
    }
    return new SceneView(solids);
  }

  private static AtomView.Vec vec(Vec3 v) {
    return new AtomView.Vec(v.x(), v.y(), v.z());
  }
}
