package org.armgals.examples.sim;

import java.util.ArrayList;
import java.util.List;
import org.armgals.examples.plot.AtomView;
import org.armgals.examples.plot.SceneView;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.LegSensors;
import org.armgals.maam.sim.Obstacle;
import org.armgals.maam.sim.Quat;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Vec3;
import org.armgals.maam.spi.Leg;

/**
 * Atoms as the pictures draw them, from their sensor readings: the kernel where it is, each leg
 * pivoting on the kernel's surface (where the simulator's universal joint is) and turned as that
 * joint turns it: about its second axis, then about its first ({@code Frames.axis1}, {@code axis2}
 * of maam-sim), each by minus the angle the joint reads (the engine measures the kernel's turn
 * against the leg, not the leg's against the kernel), then by the atom's orientation. {@code
 * ViewsTest} holds this to the simulator: a turned leg's tip, seen here, is where its proximity ray
 * starts.
 *
 * <p>A scene's obstacles as the pictures draw them: a box as a block between its corners, a pipe as
 * a tube whose outer radius is its inner radius plus its wall (its 16 staves drawn round).
 */
final class Views {
  private Views() {}

  static AtomView of(AtomSensors atom, AtomParams params) {
    double r = params.kernelRadius();
    double length = params.legLength();
    List<AtomView.Leg> legs = new ArrayList<>(6);
    for (Leg leg : Leg.values()) {
      LegSensors sensed = atom.leg(leg);
      double[] pivot = rotate(atom.orientation(), rest(leg));
      double[] d = turn(rest(leg), axis2(leg), -sensed.angle2());
      d = turn(d, axis1(leg), -sensed.angle1());
      d = rotate(atom.orientation(), d);
      legs.add(
          new AtomView.Leg(
              new AtomView.Vec(
                  atom.position().x() + r * pivot[0] + length * d[0],
                  atom.position().y() + r * pivot[1] + length * d[1],
                  atom.position().z() + r * pivot[2] + length * d[2]),
              sensed.neighbour().isPresent()));
    }
    return new AtomView(
        String.valueOf(atom.id()),
        new AtomView.Vec(atom.position().x(), atom.position().y(), atom.position().z()),
        params.kernelRadius(),
        legs);
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

  private static double[] rest(Leg leg) {
    return switch (leg) {
      case PX -> new double[] {1, 0, 0};
      case MX -> new double[] {-1, 0, 0};
      case PY -> new double[] {0, 1, 0};
      case MY -> new double[] {0, -1, 0};
      case PZ -> new double[] {0, 0, 1};
      case MZ -> new double[] {0, 0, -1};
    };
  }

  private static double[] axis1(Leg leg) {
    return switch (leg) {
      case PX, MX -> new double[] {0, 1, 0};
      case PY, MY -> new double[] {0, 0, 1};
      case PZ, MZ -> new double[] {1, 0, 0};
    };
  }

  private static double[] axis2(Leg leg) {
    return switch (leg) {
      case PX, MX -> new double[] {0, 0, 1};
      case PY, MY -> new double[] {1, 0, 0};
      case PZ, MZ -> new double[] {0, 1, 0};
    };
  }

  /** {@code v} turned by {@code angle} about the unit {@code axis} (Rodrigues). */
  private static double[] turn(double[] v, double[] k, double angle) {
    double c = Math.cos(angle);
    double s = Math.sin(angle);
    double dot = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    double[] cross = {
      k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]
    };
    double[] out = new double[3];
    for (int i = 0; i < 3; i++) {
      out[i] = v[i] * c + cross[i] * s + k[i] * dot * (1 - c);
    }
    return out;
  }

  private static double[] rotate(Quat q, double[] v) {
    double tx = 2 * (q.y() * v[2] - q.z() * v[1]);
    double ty = 2 * (q.z() * v[0] - q.x() * v[2]);
    double tz = 2 * (q.x() * v[1] - q.y() * v[0]);
    return new double[] {
      v[0] + q.w() * tx + (q.y() * tz - q.z() * ty),
      v[1] + q.w() * ty + (q.z() * tx - q.x() * tz),
      v[2] + q.w() * tz + (q.x() * ty - q.y() * tx)
    };
  }
}
