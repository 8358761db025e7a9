package org.armgals.maam.sim;

/**
 * How a simulated leg moves (docs/simulator.md, "The atom"; decision 0029). Both models keep
 * gravity, friction, contacts, the cone, the servo's speed and torque limits, bindings that carry
 * forces and break, and the energy model; they differ in what the engine solves.
 */
public enum LegDynamics {
  /**
   * An atom is one rigid body (kernel and legs, its mass and inertia those of the rest pose); each
   * leg is a capsule of that body whose pose follows its servo within the speed limit, yields when
   * its load exceeds the torque limit, and pushes on what it touches through the contacts' surface
   * velocity. A binding fixes two kernels at the pose their bound legs set. About an order of
   * magnitude faster than {@link #JOINTED}. The default, and the model the example robots are tuned
   * for (decision 0065).
   */
  KINEMATIC,
  /**
   * Each leg a body of its own on a motorized universal joint (seven bodies and six joints per
   * atom), a binding a fixed joint between two legs: the legs' own inertia and the joints'
   * compliance are simulated, at about ten times the cost.
   */
  JOINTED
}
