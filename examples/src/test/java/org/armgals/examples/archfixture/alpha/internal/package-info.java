/** Fixture for ModuleBoundariesTest: the internals of module "alpha". */
@NullMarked
package org.armgals.examples.archfixture.alpha.internal;

import org.jspecify.annotations.NullMarked;
