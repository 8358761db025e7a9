/**
 * What users plug into the simulator: the controller each atom runs every control cycle, and the
 * pacer that holds virtual time to real time.
 */
@NullMarked
package org.armgals.maam.sim.spi;

import org.jspecify.annotations.NullMarked;
