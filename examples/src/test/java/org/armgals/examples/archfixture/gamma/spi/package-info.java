/** Fixture for ModuleBoundariesTest: what users plug into module "gamma". */
@NullMarked
package org.armgals.examples.archfixture.gamma.spi;

import org.jspecify.annotations.NullMarked;
