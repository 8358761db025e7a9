/**
 * The GALS benchmarks, run by {@link org.armgals.bench.gals.Gals} ({@code benchmarks/gals.sh}): one
 * named {@link org.armgals.bench.gals.GalsBenchmark} per line of output ({@code jitter} here; the
 * MAAM framework's {@code reschedule} and {@code cycle-overhead} join the same registry).
 */
@NullMarked
package org.armgals.bench.gals;

import org.jspecify.annotations.NullMarked;
