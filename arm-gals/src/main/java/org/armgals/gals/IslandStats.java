package org.armgals.gals;

import java.time.Duration;

/**
 * What an island measured of itself since it was built.
 *
 * @param instants how many cycles it ran
 * @param overruns how many cycles ended after the next release was due (lateness of the release
 *     plus adaptation plus reactions longer than the period)
 * @param skipped how many releases {@link OverrunPolicy#SKIP} dropped
 * @param meanPeriod the mean time between two releases (zero before the second)
 * @param jitterP50 the median lateness of a release behind its schedule (zero when stepped by hand)
 * @param jitterP99 the 99th percentile of that lateness
 * @param jitterMax the largest lateness
 * @param cycleMax the longest cycle, from the release to the end of the last adaptation or reaction
 * @param adaptations how many adaptation requests were applied
 * @param adaptationMax the longest time spent applying the requests of one cycle
 * @param adaptationOverruns how many overruns the adaptation caused: cycles that would have fit
 *     their period without it
 * @param failures how many reactions threw
 */
public record IslandStats(
    long instants,
    long overruns,
    long skipped,
    Duration meanPeriod,
    Duration jitterP50,
    Duration jitterP99,
    Duration jitterMax,
    Duration cycleMax,
    long adaptations,
    Duration adaptationMax,
    long adaptationOverruns,
    long failures) {}
