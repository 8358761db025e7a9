package org.armgals.active;

import java.util.List;

/**
 * Waiting on a future would deadlock: the future's completion depends, directly or through other
 * waiting objects, on the object that wants to wait. Thrown by {@link Future#touch()} and {@link
 * FutureValue#getValue()} instead of hanging.
 */
public final class WaitCycleException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** The objects on the cycle, starting and ending with the one that tried to wait. */
  private final transient List<Address> cycle;

  /** A wait-for cycle through {@code cycle}. */
  public WaitCycleException(List<Address> cycle) {
    super("wait-for cycle: " + String.join(" -> ", cycle.stream().map(Address::toString).toList()));
    this.cycle = List.copyOf(cycle);
  }

  /** The objects on the cycle, starting and ending with the object that tried to wait. */
  public List<Address> cycle() {
    return cycle;
  }
}
