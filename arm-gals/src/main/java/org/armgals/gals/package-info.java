/**
 * ARM[GALS] (paper §5.2-5.3): reactive entities on synchronous islands, islands composed
 * asynchronously.
 *
 * <p>An {@link org.armgals.gals.Island} is a set of {@link org.armgals.gals.ReactiveEntity reactive
 * entities} released together once per period: each takes the events waiting at the release and
 * runs its {@link org.armgals.gals.Reaction reactions}; what one emits at instant {@code k} is seen
 * from {@code k + 1}, in its own island or in another one (at that island's next release). Futures
 * between entities are events too ({@link org.armgals.gals.AwaitedValue}: active wait, time-outs,
 * cancelled with the reaction that awaits them). PendingAdaptation requests are applied between
 * instants, at the {@link org.armgals.kernel.AdaptationPoint} the island was built with, and their
 * time is counted in the cycle's budget. An island is stepped by hand ({@link
 * org.armgals.gals.Island#step()}, deterministic: same inputs, same per-cycle trace hash, whatever
 * the number of workers) or paced by a real-time runner with an {@link
 * org.armgals.gals.OverrunPolicy}; either way it reports its {@link org.armgals.gals.IslandStats}.
 */
@NullMarked
package org.armgals.gals;

import org.jspecify.annotations.NullMarked;
