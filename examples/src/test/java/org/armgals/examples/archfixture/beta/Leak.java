package org.armgals.examples.archfixture.beta;

import org.armgals.examples.archfixture.alpha.internal.Secret;

/** Fixture: module "beta" reaching into alpha's internals, which the rule must report. */
public final class Leak {
  public static int steal() {
    return Secret.value();
  }
}
