/** Fixture for ModuleBoundariesTest: module "beta". */
@NullMarked
package org.armgals.examples.archfixture.beta;

import org.jspecify.annotations.NullMarked;
