package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.reflect.RecordComponent;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Reads scenes from their text format and holds the built-in ones. The format is line based (see
 * docs/simulator.md): a keyword and its values, separated by blanks; {@code #} starts a comment.
 *
 * <pre>
 * scene pair
 * param bindStrength 80
 * gravity 0 0 -9.81
 * box 1 0 0.05  0.4 1 0.1
 * pipe 0 0 0.2  x 0.15 0.01 2
 * atom 1 0 0 0.2
 * atom 2 0.22 0 0.2
 * bond 1:+x 2:-x
 * </pre>
 */
public final class Scenes {

  private static final Map<String, String> BUILT_IN = new TreeMap<>();

  static {
    BUILT_IN.put("single", "scene single\natom 1 0 0 0.07 tripod\n");
    BUILT_IN.put("pair", "scene pair\natom 1 0 0 0.12\natom 2 0.22 0 0.12\nbond 1:+x 2:-x\n");
    BUILT_IN.put(
        "chain4",
        "scene chain4\n"
            + "atom 1 0 0 0.12\natom 2 0.22 0 0.12\natom 3 0.44 0 0.12\natom 4 0.66 0 0.12\n"
            + "bond 1:+x 2:-x\nbond 2:+x 3:-x\nbond 3:+x 4:-x\n");
    BUILT_IN.put(
        "steps",
        "scene steps\n"
            + "box 0.6 0 0.03 0.2 1 0.06\nbox 0.8 0 0.06 0.2 1 0.12\n"
            + "atom 1 0 0 0.07 tripod\natom 2 0 0.3 0.07 tripod\n");
    BUILT_IN.put(
        "pipe",
        "scene pipe\npipe 0.3 0 0.2 x 0.16 0.01 1.2\n"
            + "atom 1 0 0 0.2\natom 2 0.22 0 0.2\nbond 1:+x 2:-x\n");
    BUILT_IN.put(
        "walls",
        "scene walls\nbox 0 0.4 0.15 2 0.05 0.3\nbox 0 -0.4 0.15 2 0.05 0.3\n"
            + "atom 1 0 0 0.07 tripod\n");
  }

  private Scenes() {}

  /** The names of the built-in scenes. */
  public static List<String> builtInNames() {
    return List.copyOf(BUILT_IN.keySet());
  }

  /** The built-in scene {@code name} (one of {@link #builtInNames()}). */
  public static Scene builtIn(String name) {
    requireNonNull(name, "name");
    String text = BUILT_IN.get(name);
    if (text == null) {
      throw new IllegalArgumentException(
          "no built-in scene '" + name + "'; built in: " + builtInNames());
    }
    return parse(text);
  }

  /**
   * {@code count} free atoms in tripod pose on a square grid on flat ground, {@code spacing} metres
   * apart (the benchmark's scene).
   */
  public static Scene grid(int count, double spacing) {
    if (count < 1) {
      throw new IllegalArgumentException("grid of " + count + " atoms: expected >= 1");
    }
    if (!(spacing > 0)) {
      throw new IllegalArgumentException("grid spacing " + spacing + " m: expected > 0");
    }
    int side = (int) Math.ceil(Math.sqrt(count));
    List<Scene.Placement> atoms = new ArrayList<>();
    for (int i = 0; i < count; i++) {
      atoms.add(
          new Scene.Placement(
              i + 1, new Vec3((i % side) * spacing, (i / side) * spacing, 0.07), Quat.tripod()));
    }
    return new Scene(
        "grid" + count, AtomParams.defaults(), new Vec3(0, 0, -9.81), List.of(), atoms, List.of());
  }

  /** Reads a scene file (UTF-8). */
  public static Scene load(Path file) {
    requireNonNull(file, "file");
    try {
      return parse(Files.readString(file, StandardCharsets.UTF_8));
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read scene file " + file, e);
    }
  }

  /** Parses a scene from its text; a bad line gets an exception naming its number and text. */
  public static Scene parse(String text) {
    requireNonNull(text, "text");
    return new SceneParser().parse(text);
  }

  /** The names {@code param} lines accept: the components of {@link AtomParams}. */
  static List<String> paramNames() {
    List<String> names = new ArrayList<>();
    for (RecordComponent c : AtomParams.class.getRecordComponents()) {
      names.add(c.getName());
    }
    return names;
  }
}
