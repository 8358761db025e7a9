/**
 * A Savina-style suite: the same workloads written once with armgals ({@code .armgals}) and once
 * with Apache Pekko typed actors ({@code .pekko}), run by {@link org.armgals.bench.savina.Savina}
 * (see {@code benchmarks/savina.sh} and {@code docs/benchmarks.md}).
 *
 * <p>This package holds what both implementations share: the workload sizes, the run protocol, the
 * checks and the heap probe, so that neither side measures differently.
 */
@NullMarked
package org.armgals.bench.savina;

import org.jspecify.annotations.NullMarked;
