package org.armgals.maam;

import org.armgals.kernel.Adaptation;
import org.armgals.kernel.spi.InstantContext;
import org.armgals.kernel.spi.ReactiveProgram;

/**
 * Runs a robot as a kernel entity (paper figure 8): the robot's cycle is the entity's program, and
 * the kernel's adaptation requests for it are applied to its program at the entity's adaptation
 * point. The one class that knows how a robot sits in the kernel.
 */
final class KernelHost implements ReactiveProgram {
  private final AbstractRobot robot;

  KernelHost(AbstractRobot robot) {
    this.robot = robot;
  }

  @Override
  public void react(InstantContext instant) {
    robot.kernelCycle(instant);
  }

  @Override
  public void adapt(Adaptation adaptation) {
    switch (adaptation) {
      case Adaptation.ApplyBehavior a -> {
        if (!(a.input() instanceof org.armgals.maam.Adaptation change)) {
          throw new IllegalArgumentException(
              "robot "
                  + robot.name()
                  + " cannot apply "
                  + a.behavior()
                  + " with "
                  + a.input()
                  + "; expected a program change (RobotKind.request)");
        }
        if (!RobotAdaptations.name(change).equals(a.behavior())) {
          throw new IllegalArgumentException(
              "behavior " + a.behavior() + " does not match the change " + change);
        }
        robot.applyOrRefuse(change);
      }
      case Adaptation.SetNotification s -> {}
    }
  }
}
