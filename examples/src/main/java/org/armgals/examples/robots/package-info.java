/**
 * The example robots that {@code armgals run} drives on the simulator, each a {@link
 * org.armgals.examples.sim.SimExample} built with the MAAM framework: schemas of perceptors,
 * reactors and actuators, subsumption connectors, and meta levels that adapt the robots and tell
 * the run's journal why.
 */
@NullMarked
package org.armgals.examples.robots;

import org.jspecify.annotations.NullMarked;
