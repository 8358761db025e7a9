package org.armgals.examples.archfixture.alpha.internal;

/** Fixture: an internal class of module "alpha". */
public final class Secret {
  public static int value() {
    return 42;
  }
}
