package org.armgals.active.spi;

import org.armgals.active.Address;
import org.armgals.active.FutureValue;

/**
 * Names of objects that runtimes share: a runtime registers an object's address under a name, and
 * any runtime linked to it looks the name up. The JMS transport is one ({@code
 * org.armgals.active.jms.JmsTransport}); the kernel looks its remote entities up through this
 * interface, naming no transport.
 *
 * <p>Thread-safe.
 */
public interface NameService {

  /**
   * Registers {@code address} under {@code name}, replacing what was there.
   *
   * @throws IllegalArgumentException {@code name} is blank
   */
  void register(String name, Address address);

  /** Removes the name this runtime registered, if any. */
  void unregister(String name);

  /**
   * The address registered under {@code name}, in this runtime or another. The future fails with
   * {@link org.armgals.active.FutureTimeoutException} when no runtime answers in time.
   */
  FutureValue<Address> lookup(String name);
}
