package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.ode4j.math.DVector3;

/**
 * Finds which locked, free tips may bind: pairs of tips of different atoms within the distance and
 * alignment tolerances, found through a grid of cells one tolerance wide.
 */
final class TipMatcher {

  private final double distance;
  private final double alignment;

  TipMatcher(AtomParams params) {
    this.distance = params.bindDistance();
    this.alignment = params.bindAlignment();
  }

  /** Whether tips {@code a} and {@code b} are close enough and face each other closely enough. */
  boolean inTolerance(LegModel a, LegModel b) {
    if (a.tip().distance(b.tip()) > distance) {
      return false;
    }
    DVector3 da = a.direction();
    DVector3 db = b.direction();
    double cos = -(da.get0() * db.get0() + da.get1() * db.get1() + da.get2() * db.get2());
    return Math.acos(Math.max(-1, Math.min(1, cos))) <= alignment;
  }

  /** Whether {@code leg}'s tip is locked and free, so that it may bind if its atom works. */
  static boolean lockedAndFree(LegModel leg) {
    return leg.locked && leg.binding == null && !leg.failed;
  }

  /**
   * The pairs to bind now: each locked, free tip of a working atom with the nearest such tip of
   * another atom in tolerance. Tips are visited in the order of atom ids and legs, and a tip is
   * paired at most once, so the result is deterministic.
   */
  List<LegModel[]> pairs(List<AtomModel> atoms) {
    Map<Long, List<LegModel>> grid = new HashMap<>();
    List<LegModel> candidates = new ArrayList<>();
    for (AtomModel atom : atoms) {
      if (atom.failed) {
        continue;
      }
      for (LegModel leg : atom.legs) {
        if (lockedAndFree(leg)) {
          candidates.add(leg);
          grid.computeIfAbsent(key(leg.tip(), 0, 0, 0), k -> new ArrayList<>()).add(leg);
        }
      }
    }
    List<LegModel[]> pairs = new ArrayList<>();
    Set<LegModel> taken = Collections.newSetFromMap(new IdentityHashMap<>());
    for (LegModel leg : candidates) {
      if (taken.contains(leg)) {
        continue;
      }
      DVector3 t = leg.tip();
      LegModel best = null;
      double bestDistance = Double.MAX_VALUE;
      for (int dx = -1; dx <= 1; dx++) {
        for (int dy = -1; dy <= 1; dy++) {
          for (int dz = -1; dz <= 1; dz++) {
            for (LegModel other : grid.getOrDefault(key(t, dx, dy, dz), List.of())) {
              if (other.atom == leg.atom || taken.contains(other) || !inTolerance(leg, other)) {
                continue;
              }
              double d = t.distance(other.tip());
              if (d < bestDistance) {
                best = other;
                bestDistance = d;
              }
            }
          }
        }
      }
      if (best != null) {
        taken.add(leg);
        taken.add(best);
        pairs.add(new LegModel[] {leg, best});
      }
    }
    return pairs;
  }

  private long key(DVector3 p, int dx, int dy, int dz) {
    long x = (long) Math.floor(p.get0() / distance) + dx;
    long y = (long) Math.floor(p.get1() / distance) + dy;
    long z = (long) Math.floor(p.get2() / distance) + dz;
    return (x * 73856093L) ^ (y * 19349663L) ^ (z * 83492791L);
  }
}
