package org.armgals.maam;

import org.armgals.kernel.Adaptation;
import org.armgals.kernel.spi.InstantContext;
import org.armgals.kernel.spi.ReactiveProgram;
import org.armgals.representation.Behaviors;

/**
 * Runs a robot as a kernel entity (paper figure 8): the robot's cycle is the entity's program, the
 * kernel's adaptation requests for it are applied to its program at the entity's adaptation point,
 * and its kind's changes reach its catalog. The one class that knows how a robot sits in the
 * kernel.
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
      case Adaptation.ApplyBehavior a -> robot.applyRequest(a);
      case Adaptation.SetNotification s -> {}
    }
  }

  @Override
  public void harmonized(Behaviors<?> behaviors) {
    robot.catalogChanged(behaviors);
  }
}
