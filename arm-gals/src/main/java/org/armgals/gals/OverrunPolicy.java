package org.armgals.gals;

/**
 * What a real-time island does when a cycle (adaptation included) ends after the next release was
 * due. The overrun is counted whatever the policy; an island stepped by hand has no schedule to
 * keep, so there the policy changes nothing but the overrun is still counted.
 */
public enum OverrunPolicy {
  /**
   * Keep the schedule and drop the releases that were missed: the next release is the first one of
   * the original schedule still ahead. Each dropped release is counted in {@link
   * IslandStats#skipped()}.
   */
  SKIP,

  /**
   * Keep the schedule and run the missed releases back to back, each as soon as the previous cycle
   * ends, until the island is on time again: no release is lost.
   */
  CATCH_UP,

  /**
   * Only count it: the next release comes as soon as the late cycle ends, and the schedule moves by
   * the overrun (nothing is dropped and nothing is added; the island drifts).
   */
  REPORT_ONLY
}
