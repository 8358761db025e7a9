package org.armgals.examples.sim;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.examples.plot.AtomView;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.Obstacle;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Vec3;

/**
 * The events of the live view ({@link RunWatcher}) as JSON, the same for a run and for a trace
 * played back ({@link Playback}). Lengths in metres, times in seconds, rounded to 0.01 mm and 0.01
 * ms: a picture needs no more.
 *
 * <ul>
 *   <li>start: {@code mode} ("live" or "view"), {@code example}, {@code scene}, {@code cycles},
 *       {@code period}, {@code speed}, {@code kernelRadius}, {@code legLength}, {@code obstacles}
 *       (each {@code {"type":"box","c":[x,y,z],"size":[x,y,z]}} or {@code
 *       {"type":"pipe","c":[x,y,z],"axis":"x","inner":r,"wall":w,"length":l}}; the ground is z =
 *       0);
 *   <li>frame: {@code cycle}, {@code t}, {@code energy} (all atoms'), {@code atoms} (each {@code
 *       id}, {@code c} its kernel's centre, {@code energy}, {@code failed}, {@code legs}: each
 *       {@code [x,y,z,bound]} of its tip), {@code programs} (by robot: {@code schemas} and {@code
 *       schedule}, the modules in the order they run), {@code models} (by robot: the meta's model
 *       of it, when the meta runs in the robots' JVM);
 *   <li>end: {@code ran}, {@code of}.
 * </ul>
 */
final class LiveJson {
  private LiveJson() {}

  static String start(
      String mode, String example, Scene scene, long cycles, Duration period, double speed) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("mode", mode);
    m.put("example", example);
    m.put("scene", scene.name());
    m.put("cycles", cycles);
    m.put("period", period.toNanos() / 1e9);
    m.put("speed", speed);
    m.put("kernelRadius", scene.params().kernelRadius());
    m.put("legLength", scene.params().legLength());
    List<Object> obstacles = new ArrayList<>();
    for (Obstacle o : scene.obstacles()) {
      Map<String, Object> x = new LinkedHashMap<>();
      switch (o) {
        case Obstacle.Box b -> {
          x.put("type", "box");
          x.put("c", vec(b.center()));
          x.put("size", vec(b.size()));
        }
        case Obstacle.Pipe p -> {
          x.put("type", "pipe");
          x.put("c", vec(p.center()));
          x.put("axis", String.valueOf(p.axis()));
          x.put("inner", p.innerRadius());
          x.put("wall", p.wall());
          x.put("length", p.length());
        }
      }
      obstacles.add(x);
    }
    m.put("obstacles", obstacles);
    return LoopJson.write(m);
  }

  static String frame(
      long cycle,
      long nanos,
      List<AtomSensors> atoms,
      AtomParams params,
      Map<String, Object> programs,
      Map<String, Object> models) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("cycle", cycle);
    m.put("t", round(nanos / 1e9));
    double total = 0;
    List<Object> views = new ArrayList<>();
    for (AtomSensors s : atoms) {
      AtomView v = Views.of(s, params);
      Map<String, Object> a = new LinkedHashMap<>();
      a.put("id", s.id());
      a.put("c", vec(v.centre()));
      a.put("energy", round(s.energy()));
      a.put("failed", s.failed());
      List<Object> legs = new ArrayList<>();
      for (AtomView.Leg leg : v.legs()) {
        List<Object> tip = new ArrayList<>(vec(leg.tip()));
        tip.add(leg.bound());
        legs.add(tip);
      }
      a.put("legs", legs);
      views.add(a);
      total += s.energy();
    }
    m.put("energy", round(total));
    m.put("atoms", views);
    m.put("programs", programs);
    m.put("models", models);
    return LoopJson.write(m);
  }

  static String end(long ran, long of) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("ran", ran);
    m.put("of", of);
    return LoopJson.write(m);
  }

  private static List<Object> vec(Vec3 v) {
    return List.of(round(v.x()), round(v.y()), round(v.z()));
  }

  private static List<Object> vec(AtomView.Vec v) {
    return List.of(round(v.x()), round(v.y()), round(v.z()));
  }

  private static double round(double v) {
    return Math.round(v * 1e5) / 1e5;
  }
}
