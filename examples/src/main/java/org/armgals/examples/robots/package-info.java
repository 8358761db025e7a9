/**
 * The example robots of {@code armgals run}: each a {@link org.armgals.examples.sim.SimExample}
 * whose atoms run MAAM robots (schemas of perceptors, reactors and actuators joined by subsumption
 * connectors) under meta levels that adapt them while they run.
 */
@NullMarked
package org.armgals.examples.robots;

import org.jspecify.annotations.NullMarked;
