package org.armgals.kernel;

import java.util.Map;

/**
 * A behavioral meta over JMX ({@code org.armgals.kernel:type=BehavioralMeta,...}): its models,
 * their staleness and its filters, per base entity (keyed by the entity's name).
 */
public interface BehavioralMetaMXBean {
  /** The state each model believes its entity is in. */
  Map<String, String> getModels();

  /** How long since each model last heard from its entity, in milliseconds. */
  Map<String, Long> getStalenessMillis();

  /** Each entity's filter. */
  Map<String, String> getFilters();

  /** The last adaptation version each entity acknowledged. */
  Map<String, Long> getAppliedVersions();

  /** Whether each entity's runtime was reported lost and nothing was heard from it since. */
  Map<String, Boolean> getLost();

  /** The adaptations the damping held back, over all entities. */
  long getSuppressedAdaptations();
}
