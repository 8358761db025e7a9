package org.armgals.kernel;

/**
 * An entity over JMX ({@code org.armgals.kernel:type=Entity,runtime=...,name=...}): read-only
 * snapshots, never waiting for the entity.
 */
public interface EntityMXBean {
  /** The entity's name. */
  String getName();

  /** Its address. */
  String getAddress();

  /** The name of its structural meta. */
  String getStructuralMeta();

  /** The name of its behavioral meta, empty if none. */
  String getBehavioralMeta();

  /** Its state, as observed. */
  String getState();

  /** The names of its behaviors. */
  String[] getBehaviors();

  /** What it notifies. */
  String getNotificationPolicy();

  /** The version of the last adaptation it applied. */
  long getAppliedVersion();

  /**
   * How many of its adaptation points took longer than its clock's period applying their requests
   * (the cycle's time budget); 0 for an entity without a clock.
   */
  long getAdaptationOverruns();

  /** The longest one of its adaptation points took applying its requests, in nanoseconds. */
  long getAdaptationMaxNanos();

  /** How many times it stopped waiting for a meta in lock step (it runs free since). */
  long getLockStepTimeouts();

  /** The events waiting in its buffer. */
  int getQueueDepth();
}
