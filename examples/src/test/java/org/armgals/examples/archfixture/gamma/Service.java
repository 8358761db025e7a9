package org.armgals.examples.archfixture.gamma;

import org.armgals.examples.archfixture.gamma.spi.Plugin;

/** Fixture: module "gamma"'s API, which takes a plug-in that in turn takes the API's values. */
public final class Service {
  public static int run(Plugin plugin) {
    return plugin.apply(new Service());
  }

  public int value() {
    return 7;
  }
}
