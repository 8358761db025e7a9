/**
 * Testing with armgals under JUnit 5 (docs/testing.md).
 *
 * <ul>
 *   <li>{@link org.armgals.testkit.ActiveTest} and {@link
 *       org.armgals.testkit.ActiveRuntimeExtension}: a runtime for each test, on a manual clock if
 *       the test asks, shut down after it; a test fails if one of its objects failed.
 *   <li>{@link org.armgals.testkit.Stepper}: steps a manual clock and the islands a test drives by
 *       hand, by a number of instants or until a condition holds.
 *   <li>{@link org.armgals.testkit.Probe}: an active object that a test sends to and expects
 *       messages from, within a number of instants (manual clock) or a time (real clock).
 *   <li>{@link org.armgals.testkit.BrokerTest} and {@link
 *       org.armgals.testkit.EmbeddedBrokerExtension}: an embedded broker on {@code 127.0.0.1} for
 *       tests of several runtimes, with transports and runtimes closed after each test.
 * </ul>
 *
 * <p>The testkit depends on arm-active only (and, optionally, on the Artemis broker that {@link
 * org.armgals.testkit.EmbeddedBrokerExtension} starts), so every module above arm-active can use it
 * in its tests; arm-active's own tests cannot.
 */
@NullMarked
package org.armgals.testkit;

import org.jspecify.annotations.NullMarked;
