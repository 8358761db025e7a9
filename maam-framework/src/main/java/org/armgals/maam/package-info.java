/**
 * The MAAM reactive framework (paper §5.4, figure 8): robots made of schemas of behavior modules,
 * scheduled once per synchronous cycle, with subsumption connectors, which are kernel entities
 * reflected on asynchronously by behavioral meta-entities.
 *
 * <p>A robot programmer takes four steps: design {@link org.armgals.maam.Schema schemas}; write
 * {@link org.armgals.maam.Perceptor}, {@link org.armgals.maam.Reactor} and {@link
 * org.armgals.maam.Actuator} classes; write {@link org.armgals.maam.Signal} classes for what flows
 * between them; write a robot class extending {@link org.armgals.maam.AbstractRobot} that registers
 * them. The {@link org.armgals.maam.Scheduler} orders the modules; a {@link
 * org.armgals.maam.MetaRobot} holds the robot's program and reschedules it. {@link
 * org.armgals.maam.AbstractRobot#start} makes a robot a kernel entity of its {@link
 * org.armgals.maam.RobotKind kind} on an arm-gals island; its {@link org.armgals.maam.BMetaRobot},
 * a behavioral meta-entity in the same JVM or another, is notified at each cycle, models it and
 * asks for adaptations by name ({@code setScheduling}, {@code changeModule}...), which the robot
 * builds from its kind's catalog and applies at the island's adaptation point. The body a robot
 * reads and drives is the SPI in {@code org.armgals.maam.spi}.
 */
@NullMarked
package org.armgals.maam;

import org.jspecify.annotations.NullMarked;
