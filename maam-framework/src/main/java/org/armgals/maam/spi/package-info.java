/**
 * The body SPI: the sensors a robot reads and the actuators it drives, implemented by the simulator
 * of MAAM atoms and, one day, by real hardware.
 *
 * <p>A {@link org.armgals.maam.spi.Body} is a set of named, typed {@link
 * org.armgals.maam.spi.SensorKey sensors} and {@link org.armgals.maam.spi.ActuatorKey actuators};
 * {@link org.armgals.maam.spi.Atom} names those of a MAAM atom (six legs, each in a cone, leg-tip
 * contact and binding, proximity, tilt, battery energy, neighbour messages). The test double,
 * {@code FakeBody}, is in the testkit (armgals-testkit-maam, {@code org.armgals.testkit.maam}).
 */
@NullMarked
package org.armgals.maam.spi;

import org.jspecify.annotations.NullMarked;
