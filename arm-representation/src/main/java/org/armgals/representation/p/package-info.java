/**
 * The procedural family, ARM[·](P) of paper §3.2: a state is the values of an entity's fields
 * ({@link org.armgals.representation.p.PState}, a name-to-value map that can be made from and
 * turned back into a record), the space is the product of the fields' types ({@link
 * org.armgals.representation.p.PSpace}), and the behaviors are its methods: a method dictionary of
 * named pure functions with guards ({@link org.armgals.representation.p.PMethod}).
 */
@NullMarked
package org.armgals.representation.p;

import org.jspecify.annotations.NullMarked;
