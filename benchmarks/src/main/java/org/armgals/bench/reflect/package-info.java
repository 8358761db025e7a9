/**
 * The reflective loop's figures ({@code benchmarks/reflect.sh}): what a robot notifying its meta
 * level every cycle costs, how long a request takes from the notification it was decided on to
 * being applied (a meta in the robots' JVM or in another), and the cycles a real-time run misses
 * with its meta in another JVM. {@link org.armgals.bench.reflect.Asking} is the benchmark's own
 * example, found as a {@link org.armgals.examples.sim.SimExample} service.
 */
@NullMarked
package org.armgals.bench.reflect;

import org.jspecify.annotations.NullMarked;
