package org.armgals.maam;

/**
 * Where a module emits during its step. A signal emitted on an output port is seen by the modules
 * connected to it later in the same cycle (they are scheduled after); emitting twice on one port
 * keeps the last signal. Valid only during the step it is given to, on the robot's thread.
 */
public interface Outputs {

  /**
   * Emits {@code signal} on {@code port}.
   *
   * @throws IllegalArgumentException {@code port} is not an output of the module, or {@code signal}
   *     is not of its type
   */
  <S extends Signal> void emit(Port<S> port, S signal);
}
