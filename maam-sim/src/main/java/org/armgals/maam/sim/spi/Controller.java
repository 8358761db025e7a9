package org.armgals.maam.sim.spi;

import static java.util.Objects.requireNonNull;

import org.armgals.maam.spi.Body;

/**
 * What drives one atom: called once per control cycle, in the order of atom ids, on the thread
 * running the simulation (a {@link #confined} one may run on any of the simulation's threads). It
 * reads the body's sensors and sets its actuators; it must not block.
 *
 * <p>The body it is handed is the atom's framework {@link Body}, the very instance {@code
 * Simulation.body(id)} returns, every cycle. A robot built on that body before the first cycle is
 * stepped by {@link #driving}, which holds it to that body.
 */
@FunctionalInterface
public interface Controller {

  /** Runs control cycle number {@code cycle} (0, 1, …) for {@code body}. */
  void onCycle(Body body, long cycle);

  /**
   * Whether this controller is {@link #confined confined}: it drives only the body it is handed,
   * and shares nothing with the other atoms' controllers. False unless made by {@link #confined}.
   */
  default boolean isConfined() {
    return false;
  }

  /**
   * {@code controller}, declared confined: each cycle it reads and drives only the body it is
   * handed, through that body, and reads or writes nothing another atom's controller writes (no
   * shared robot, random source or counter, no call on the simulation). A simulation on several
   * threads ({@code SimulationBuilder.threads}) whose controllers are all confined runs them at
   * once on its threads; the run is the same as on one thread, bit for bit, for the body's sends,
   * binds and unbinds are carried out after all controllers ran, in the order of atom ids. If one
   * of them fails, the others of the cycle may have run, and the cycle's sends, binds and unbinds
   * are dropped.
   */
  static Controller confined(Controller controller) {
    requireNonNull(controller, "controller");
    return new Controller() {
      @Override
      public void onCycle(Body body, long cycle) {
        controller.onCycle(body, cycle);
      }

      @Override
      public boolean isConfined() {
        return true;
      }
    };
  }

  /** A controller that does nothing: the legs hold the targets they have (straight at first). */
  static Controller idle() {
    return (body, cycle) -> {};
  }

  /**
   * The controller of a robot built on {@code body}: each cycle it runs {@code step} (the robot's
   * cycle, which senses and acts through {@code body}), after checking that it was handed {@code
   * body}.
   *
   * @throws IllegalStateException from {@code onCycle}, if handed another body: the controller was
   *     installed for another atom, or another simulation, than its robot's
   */
  static Controller driving(Body body, Runnable step) {
    requireNonNull(body, "body");
    requireNonNull(step, "step");
    return (handed, cycle) -> {
      if (handed != body) {
        throw new IllegalStateException(
            "handed body "
                + handed.id()
                + " at cycle "
                + cycle
                + ", but the robot was built on body "
                + body.id()
                + " (another atom's or another simulation's): install the controller for the atom"
                + " whose body the robot uses");
      }
      step.run();
    };
  }
}
