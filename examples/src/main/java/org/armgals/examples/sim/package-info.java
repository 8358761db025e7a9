/**
 * Example robots on the MAAM simulator, and the run that drives them for {@code armgals run}: a
 * {@link org.armgals.examples.sim.SimExample} says what scene to build and how to drive its atoms;
 * the run steps the simulation, shows its progress, leaves the trace and the pictures in the output
 * directory, and sums the run up.
 */
@NullMarked
package org.armgals.examples.sim;

import org.jspecify.annotations.NullMarked;
