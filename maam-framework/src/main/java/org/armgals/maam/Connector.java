package org.armgals.maam;

/**
 * A subsumption connection added to a robot beside its schemas (paper §5.1, figure 5); it may join
 * modules of two schemas or of one. Its {@code source} module is always scheduled before its {@code
 * target} module. See {@code docs/maam-guide.md} for the convention.
 */
public sealed interface Connector permits Inhibitor, Suppressor, Derivator {

  /** The output port whose signal drives the connector. */
  PortRef source();

  /**
   * The port the connector acts on: an input for an inhibitor or a derivator, an output for a
   * suppressor.
   */
  PortRef target();
}
