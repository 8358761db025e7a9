/**
 * The example robots of {@code armgals run}, each a {@link org.armgals.examples.sim.SimExample} on
 * the MAAM simulator.
 */
@NullMarked
package org.armgals.examples.robots;

import org.jspecify.annotations.NullMarked;
