package org.armgals.examples.archfixture.gamma.spi;

import org.armgals.examples.archfixture.gamma.Service;

/** Fixture: module "gamma"'s SPI, which refers back to its API. */
public interface Plugin {
  int apply(Service service);
}
