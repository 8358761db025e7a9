package org.armgals.examples.archfixture.gamma.left;

import org.armgals.examples.archfixture.gamma.right.Right;

/** Fixture: a class of package left that uses package right, which uses left back. */
public final class Left {
  public static int twice() {
    return 2 * Right.one();
  }
}
