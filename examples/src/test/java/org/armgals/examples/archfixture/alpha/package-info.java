/** Fixture for ModuleBoundariesTest: module "alpha". */
@NullMarked
package org.armgals.examples.archfixture.alpha;

import org.jspecify.annotations.NullMarked;
