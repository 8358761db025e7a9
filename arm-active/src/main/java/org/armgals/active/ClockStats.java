package org.armgals.active;

import java.time.Duration;

/**
 * What a {@link Clock} measured of itself since it started.
 *
 * @param instants how many releases so far
 * @param overruns how many instants ended after the next release was due
 * @param meanPeriod the mean time between two releases (zero before the second)
 * @param jitterP50 the median lateness of a release behind its scheduled time
 * @param jitterP99 the 99th percentile of that lateness
 * @param jitterMax the largest lateness
 * @param cycleMax the longest instant (release until every object finished its cycle)
 */
public record ClockStats(
    long instants,
    long overruns,
    Duration meanPeriod,
    Duration jitterP50,
    Duration jitterP99,
    Duration jitterMax,
    Duration cycleMax) {}
