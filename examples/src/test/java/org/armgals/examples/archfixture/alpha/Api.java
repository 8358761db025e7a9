package org.armgals.examples.archfixture.alpha;

import org.armgals.examples.archfixture.alpha.internal.Secret;

/** Fixture: module "alpha"'s API, which may use its own internals. */
public final class Api {
  public static int answer() {
    return Secret.value();
  }
}
