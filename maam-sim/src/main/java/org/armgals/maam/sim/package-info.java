/**
 * A physical simulator of MAAM atoms and molecules: scenes, the simulation facade, the per-atom
 * body (sensors and actuators), faults and the per-cycle trace.
 */
@NullMarked
package org.armgals.maam.sim;

import org.jspecify.annotations.NullMarked;
