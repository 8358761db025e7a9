/**
 * JMH micro-benchmarks of the hot paths of {@code org.armgals.active}: a one-way send and its
 * processing, a synchronized request's round trip, and a guarded event's deferral and retry. Run
 * them with {@code java -jar benchmarks/target/benchmarks.jar} (see {@code docs/benchmarks.md}).
 */
@NullMarked
package org.armgals.bench.jmh;

import org.jspecify.annotations.NullMarked;
