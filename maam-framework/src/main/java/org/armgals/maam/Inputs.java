package org.armgals.maam;

import org.jspecify.annotations.Nullable;

/**
 * What a module reads during its step: the signals on its input ports this cycle. Valid only during
 * the step it is given to, on the robot's thread.
 */
public interface Inputs {

  /**
   * The signal on {@code port} this cycle, or {@code null} when there is none: no producer emitted,
   * the port is not connected, or an {@link Inhibitor} blocks it. Absence is a stimulus too.
   *
   * @throws IllegalArgumentException {@code port} is not an input of the module
   */
  <S extends Signal> @Nullable S get(Port<S> port);
}
