/**
 * The MAAM reactive framework (paper §5.4): robots made of schemas of behavior modules, scheduled
 * once per synchronous cycle, with subsumption connectors and meta-robots that adapt them.
 *
 * <p>A robot programmer takes four steps: design {@link org.armgals.maam.Schema schemas}; write
 * {@link org.armgals.maam.Perceptor}, {@link org.armgals.maam.Reactor} and {@link
 * org.armgals.maam.Actuator} classes; write {@link org.armgals.maam.Signal} classes for what flows
 * between them; write a robot class extending {@link org.armgals.maam.AbstractRobot} that registers
 * them. The {@link org.armgals.maam.Scheduler} orders the modules; a {@link
 * org.armgals.maam.MetaRobot} holds the robot's program and reschedules it; a {@link
 * org.armgals.maam.BMetaRobot} is notified every cycle and asks for adaptations, applied at the
 * {@link org.armgals.kernel.AdaptationPoint} the robot chose, or its island's: {@link
 * org.armgals.maam.AbstractRobot#start} makes a robot a reactive entity of an arm-gals island. The
 * body a robot reads and drives is the SPI in {@code org.armgals.maam.spi}.
 */
@NullMarked
package org.armgals.maam;

import org.jspecify.annotations.NullMarked;
