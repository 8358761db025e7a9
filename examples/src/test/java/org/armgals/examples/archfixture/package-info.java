/**
 * Fixtures for {@code ModuleBoundariesTest}: two pretend modules, alpha and beta, where beta breaks
 * the rules, so that the rules are seen to fail.
 */
@NullMarked
package org.armgals.examples.archfixture;

import org.jspecify.annotations.NullMarked;
