/**
 * Testing MAAM robots: {@link org.armgals.testkit.maam.FakeBody}, a body whose sensors a test sets
 * and whose actuators' commands it reads back (docs/testing.md).
 *
 * <p>A module of its own, armgals-testkit-maam, beside armgals-testkit: the testkit depends on
 * arm-active only, so that the tests of arm-kernel, arm-gals and maam-framework can use it, and a
 * body double needs maam-framework's body SPI (docs/decisions/0053).
 */
@NullMarked
package org.armgals.testkit.maam;

import org.jspecify.annotations.NullMarked;
