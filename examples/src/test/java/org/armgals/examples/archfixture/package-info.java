/**
 * Fixtures for {@code ModuleBoundariesTest}: pretend modules where one breaks each rule, so that
 * the rules are seen to fail: beta reaches into alpha's internals, alpha has a public class off its
 * API list, and gamma's packages left and right form a cycle.
 */
@NullMarked
package org.armgals.examples.archfixture;

import org.jspecify.annotations.NullMarked;
