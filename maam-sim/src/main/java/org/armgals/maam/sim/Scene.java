package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.armgals.maam.spi.Leg;

/**
 * A world and the molecules in it: what a simulation starts from. Scenes are data: {@link Scenes}
 * reads them from text (the format is in docs/simulator.md) and has a few built in.
 *
 * @param name a name for traces
 * @param params the parameters every atom shares
 * @param gravity gravity (m/s²)
 * @param obstacles fixed obstacles; the ground is the plane z = 0 and always there
 * @param atoms the atoms and where their kernels start
 * @param bonds the bindings present at the start; the two tips must be within tolerance
 */
public record Scene(
    String name,
    AtomParams params,
    Vec3 gravity,
    List<Obstacle> obstacles,
    List<Placement> atoms,
    List<Bond> bonds) {

  /** Checks ids are unique, bonds name existing atoms, and no leg is bonded twice. */
  public Scene {
    requireNonNull(name, "name");
    requireNonNull(params, "params");
    requireNonNull(gravity, "gravity");
    obstacles = List.copyOf(obstacles);
    atoms = List.copyOf(atoms);
    bonds = List.copyOf(bonds);
    Set<Integer> ids = new HashSet<>();
    for (Placement p : atoms) {
      if (!ids.add(p.id())) {
        throw new IllegalArgumentException("scene '" + name + "': atom id " + p.id() + " twice");
      }
    }
    Set<String> legs = new HashSet<>();
    for (Bond b : bonds) {
      for (int id : new int[] {b.atomA(), b.atomB()}) {
        if (!ids.contains(id)) {
          throw new IllegalArgumentException(
              "scene '" + name + "': bond " + b + " names atom " + id + ", which is not placed");
        }
      }
      if (!legs.add(b.atomA() + Legs.label(b.legA()))
          || !legs.add(b.atomB() + Legs.label(b.legB()))) {
        throw new IllegalArgumentException(
            "scene '" + name + "': bond " + b + " uses a leg that is already bonded");
      }
    }
  }

  /**
   * An atom of the scene.
   *
   * @param id its id, unique in the scene, >= 0
   * @param position where its kernel's centre starts (m)
   * @param orientation how its kernel is turned at the start
   */
  public record Placement(int id, Vec3 position, Quat orientation) {
    /** Checks the id. */
    public Placement {
      if (id < 0) {
        throw new IllegalArgumentException("atom id " + id + " is negative");
      }
      requireNonNull(position, "position");
      requireNonNull(orientation, "orientation");
    }
  }

  /**
   * A binding present at the start.
   *
   * @param atomA one atom
   * @param legA its leg
   * @param atomB the other atom
   * @param legB its leg, facing {@code legA}
   */
  public record Bond(int atomA, Leg legA, int atomB, Leg legB) {
    /** Checks the two ends differ. */
    public Bond {
      requireNonNull(legA, "legA");
      requireNonNull(legB, "legB");
      if (atomA == atomB) {
        throw new IllegalArgumentException("bond binds atom " + atomA + " to itself");
      }
    }

    @Override
    public String toString() {
      return atomA + ":" + Legs.label(legA) + " " + atomB + ":" + Legs.label(legB);
    }
  }
}
