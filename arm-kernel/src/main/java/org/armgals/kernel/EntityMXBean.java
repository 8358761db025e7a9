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
}
