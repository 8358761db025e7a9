package org.armgals.maam.guide;

import java.util.Map;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.RobotKind;
import org.armgals.maam.guide.Modules.Balance;
import org.armgals.representation.p.PState;

/** The balancing atom's kind in the ARM kernel: what it observes, and its catalog. */
final class BalancingKind {

  private BalancingKind() {}

  /** The gain of the {@code balance} module in a request: radians of stance per radian of lean. */
  static final String GAIN = "gain";

  // tag::kind[]
  /**
   * The kind {@code BalancingAtom}, a structural meta of {@code kernel}: its robots observe how far
   * they lean (besides {@code cycle}, {@code program}, {@code schemas} and {@code errors}), and its
   * catalog has a {@code balance} module of any gain, which a meta may ask a robot to run instead
   * of its own.
   */
  static StructuralMeta<PState> define(Kernel kernel) {
    return RobotKind.builder("BalancingAtom", BalancingAtom.class)
        .observing(Map.of(BalancingAtom.LEAN, 0.0))
        .module("balance", (robot, parameters) -> new Balance("balance", parameters.number(GAIN)))
        .define(kernel);
  }
  // end::kind[]
}
