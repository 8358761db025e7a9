/**
 * A Savina-style suite: the same workloads written three times, with armgals ({@code .armgals}),
 * with Apache Pekko typed actors ({@code .pekko}) and with hand-written actors on a fork-join pool
 * ({@code .yardstick}), run by {@link org.armgals.bench.savina.Savina} (see {@code
 * benchmarks/savina.sh} and {@code docs/benchmarks.md}).
 *
 * <p>This package holds what the implementations share: the workload sizes, the run protocol, the
 * checks and the heap probe, so that no side measures differently; and {@link
 * org.armgals.bench.savina.LineRoundTrip}, what moving a cache line between two cores costs on the
 * machine, the floor under every hand-over between threads on different cores.
 */
@NullMarked
package org.armgals.bench.savina;

import org.jspecify.annotations.NullMarked;
