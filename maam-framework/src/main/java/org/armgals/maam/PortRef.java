package org.armgals.maam;

import static java.util.Objects.requireNonNull;

/**
 * A port of a module, the module named: an end of a {@link Wire} or a {@link Connector}. Naming the
 * module rather than holding it lets a connector outlive a {@link ProgramChange.ChangeModule} of
 * either end.
 *
 * @param module the module's name
 * @param port one of its ports
 */
public record PortRef(String module, Port<?> port) {

  /** Checks for nulls. */
  public PortRef {
    requireNonNull(module, "module");
    requireNonNull(port, "port");
  }

  /** {@code port} of {@code module}. */
  public static PortRef of(BehaviorModule module, Port<?> port) {
    return new PortRef(requireNonNull(module, "module").name(), port);
  }

  @Override
  public String toString() {
    return module + "." + port.name();
  }
}
