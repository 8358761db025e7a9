package org.armgals.maam.spi;

import org.armgals.maam.sim.LegDynamics;

/** The framework's body SPI contract, held against atoms with kinematic legs. */
class KinematicSimBodyContractTest extends SimBodyContractTest {

  @Override
  LegDynamics dynamics() {
    return LegDynamics.KINEMATIC;
  }
}
