/**
 * The Savina-style workloads written with armgals active objects, the way a user of the {@code
 * org.armgals.active} API would write them: servants with plain fields, one-way {@code send}s of
 * lambdas, {@code call(...).getValue()} for answers, default object configurations unless a
 * workload says why not.
 */
@NullMarked
package org.armgals.bench.savina.armgals;

import org.jspecify.annotations.NullMarked;
