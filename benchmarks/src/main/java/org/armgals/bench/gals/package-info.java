/**
 * The GALS and MAAM benchmarks behind {@code benchmarks/gals.sh}: one entry point, {@link
 * org.armgals.bench.gals.Gals}, taking the names of the benchmarks to run and printing one {@code
 * gals name=...} line each.
 */
@NullMarked
package org.armgals.bench.gals;

import org.jspecify.annotations.NullMarked;
