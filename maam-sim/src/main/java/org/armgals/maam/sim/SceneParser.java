package org.armgals.maam.sim;

import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** Parses the line-based scene format of {@link Scenes}; one instance per parse. */
final class SceneParser {

  private String name = "unnamed";
  private Vec3 gravity = new Vec3(0, 0, -9.81);
  private final Map<String, Object> params = new LinkedHashMap<>();
  private final List<Obstacle> obstacles = new ArrayList<>();
  private final List<Scene.Placement> atoms = new ArrayList<>();
  private final List<Scene.Bond> bonds = new ArrayList<>();

  Scene parse(String text) {
    String[] lines = text.split("\\R", -1);
    for (int i = 0; i < lines.length; i++) {
      String line = lines[i];
      int hash = line.indexOf('#');
      String content = (hash >= 0 ? line.substring(0, hash) : line).strip();
      if (content.isEmpty()) {
        continue;
      }
      try {
        line(content.split("\\s+"));
      } catch (IllegalArgumentException e) {
        throw new IllegalArgumentException(
            "scene line " + (i + 1) + " '" + line.strip() + "': " + e.getMessage(), e);
      }
    }
    return new Scene(name, atomParams(), gravity, obstacles, atoms, bonds);
  }

  private void line(String[] w) {
    switch (w[0]) {
      case "scene" -> {
        arity(w, 1);
        name = w[1];
      }
      case "gravity" -> {
        arity(w, 3);
        gravity = vec(w, 1);
      }
      case "param" -> {
        arity(w, 2);
        if (!Scenes.paramNames().contains(w[1])) {
          throw new IllegalArgumentException(
              "unknown param '" + w[1] + "'; expected one of " + Scenes.paramNames());
        }
        params.put(w[1], w[1].equals("autoLock") ? bool(w[2]) : num(w[2]));
      }
      case "box" -> {
        arity(w, 6);
        obstacles.add(new Obstacle.Box(vec(w, 1), vec(w, 4)));
      }
      case "pipe" -> {
        arity(w, 7);
        if (w[4].length() != 1) {
          throw new IllegalArgumentException("pipe axis '" + w[4] + "' is not x, y or z");
        }
        obstacles.add(
            new Obstacle.Pipe(vec(w, 1), w[4].charAt(0), num(w[5]), num(w[6]), num(w[7])));
      }
      case "atom" -> atom(w);
      case "bond" -> {
        arity(w, 2);
        String[] a = end(w[1]);
        String[] b = end(w[2]);
        bonds.add(
            new Scene.Bond(integer(a[0]), Legs.ofLabel(a[1]), integer(b[0]), Legs.ofLabel(b[1])));
      }
      default ->
          throw new IllegalArgumentException(
              "unknown keyword '"
                  + w[0]
                  + "'; expected scene, param, gravity, box, pipe, atom"
                  + " or bond");
    }
  }

  private void atom(String[] w) {
    Quat orientation;
    if (w.length == 5) {
      orientation = Quat.IDENTITY;
    } else if (w.length == 6 && w[5].equals("tripod")) {
      orientation = Quat.tripod();
    } else if (w.length == 9) {
      orientation = Quat.ofAxisAngle(num(w[5]), num(w[6]), num(w[7]), Math.toRadians(num(w[8])));
    } else {
      throw new IllegalArgumentException(
          "atom takes: id x y z [tripod | axis-x axis-y axis-z angle-degrees]");
    }
    atoms.add(new Scene.Placement(integer(w[1]), vec(w, 2), orientation));
  }

  private AtomParams atomParams() {
    AtomParams d = AtomParams.defaults();
    RecordComponent[] components = AtomParams.class.getRecordComponents();
    Object[] values = new Object[components.length];
    Class<?>[] types = new Class<?>[components.length];
    for (int i = 0; i < components.length; i++) {
      types[i] = components[i].getType();
      try {
        values[i] =
            params.containsKey(components[i].getName())
                ? params.get(components[i].getName())
                : components[i].getAccessor().invoke(d);
      } catch (ReflectiveOperationException e) {
        throw new IllegalStateException("cannot read AtomParams." + components[i].getName(), e);
      }
    }
    try {
      return AtomParams.class.getDeclaredConstructor(types).newInstance(values);
    } catch (java.lang.reflect.InvocationTargetException e) {
      if (e.getCause() instanceof IllegalArgumentException bad) {
        throw new IllegalArgumentException("scene '" + name + "': " + bad.getMessage(), bad);
      }
      throw new IllegalStateException("cannot build AtomParams", e);
    } catch (ReflectiveOperationException e) {
      throw new IllegalStateException("cannot build AtomParams", e);
    }
  }

  private static String[] end(String s) {
    int colon = s.indexOf(':');
    if (colon < 0) {
      throw new IllegalArgumentException("bond end '" + s + "' is not of the form id:leg");
    }
    return new String[] {s.substring(0, colon), s.substring(colon + 1)};
  }

  private static void arity(String[] w, int n) {
    if (w.length != n + 1) {
      throw new IllegalArgumentException(
          "'" + w[0] + "' takes " + n + " values, not " + (w.length - 1));
    }
  }

  private static Vec3 vec(String[] w, int from) {
    return new Vec3(num(w[from]), num(w[from + 1]), num(w[from + 2]));
  }

  private static double num(String s) {
    try {
      if (s.endsWith("deg")) {
        return Math.toRadians(Double.parseDouble(s.substring(0, s.length() - 3)));
      }
      return Double.parseDouble(s);
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException("'" + s + "' is not a number", e);
    }
  }

  private static int integer(String s) {
    try {
      return Integer.parseInt(s);
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException("'" + s + "' is not an integer", e);
    }
  }

  private static boolean bool(String s) {
    return switch (s) {
      case "true" -> true;
      case "false" -> false;
      default -> throw new IllegalArgumentException("'" + s + "' is not true or false");
    };
  }
}
