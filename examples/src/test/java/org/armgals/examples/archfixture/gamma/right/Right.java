package org.armgals.examples.archfixture.gamma.right;

import org.armgals.examples.archfixture.gamma.left.Left;

/** Fixture: a class of package right that uses package left, closing the cycle. */
public final class Right {
  public static int one() {
    return 1;
  }

  public static int four() {
    return 2 * Left.twice();
  }
}
