/** Fixture for ModuleBoundariesTest: the other side of module "gamma"'s package cycle. */
@NullMarked
package org.armgals.examples.archfixture.gamma.right;

import org.jspecify.annotations.NullMarked;
