/**
 * The GALS benchmarks, run by {@link org.armgals.bench.gals.Gals} ({@code benchmarks/gals.sh}):
 * named benchmarks in one table ({@code jitter} here; the MAAM framework's {@code reschedule} and
 * {@code cycle-overhead} join the same table).
 */
@NullMarked
package org.armgals.bench.gals;

import org.jspecify.annotations.NullMarked;
