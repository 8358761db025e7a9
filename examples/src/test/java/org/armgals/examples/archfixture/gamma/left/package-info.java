/** Fixture for ModuleBoundariesTest: one side of module "gamma"'s package cycle. */
@NullMarked
package org.armgals.examples.archfixture.gamma.left;

import org.jspecify.annotations.NullMarked;
