/** Fixture for ModuleBoundariesTest: module "gamma", whose packages left and right form a cycle. */
@NullMarked
package org.armgals.examples.archfixture.gamma;

import org.jspecify.annotations.NullMarked;
