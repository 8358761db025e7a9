/**
 * The example robots of {@code armgals run}: each a {@link org.armgals.examples.sim.SimExample}
 * built with the MAAM framework (schemas of perceptors, reactors and actuators, connectors, meta
 * levels that adapt them), driving simulated MAAM atoms.
 */
@NullMarked
package org.armgals.examples.robots;

import org.jspecify.annotations.NullMarked;
