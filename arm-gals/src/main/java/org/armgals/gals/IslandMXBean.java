package org.armgals.gals;

/**
 * The figures of an island over JMX, registered as {@code org.armgals:type=Island,runtime="<runtime
 * name>",name="<island name>"} while the island is open (when built with {@link
 * Island.Builder#jmx(boolean) jmx} on). See {@link IslandStats} for their meaning; durations are in
 * nanoseconds.
 */
public interface IslandMXBean {
  /** The island's name. */
  String getName();

  /** The period, in nanoseconds. */
  long getPeriodNanos();

  /** Cycles run. */
  long getInstants();

  /** Cycles that ended after the next release was due. */
  long getOverruns();

  /** Releases dropped by {@link OverrunPolicy#SKIP}. */
  long getSkipped();

  /** The mean time between two releases. */
  long getMeanPeriodNanos();

  /** The median lateness of a release. */
  long getJitterP50Nanos();

  /** The 99th percentile of the lateness of a release. */
  long getJitterP99Nanos();

  /** The largest lateness of a release. */
  long getJitterMaxNanos();

  /** The longest cycle. */
  long getCycleMaxNanos();

  /** Adaptation requests applied. */
  long getAdaptations();

  /** Overruns the adaptation caused. */
  long getAdaptationOverruns();

  /** Reactions that threw. */
  long getFailures();

  /** Its reactive entities. */
  int getEntities();
}
