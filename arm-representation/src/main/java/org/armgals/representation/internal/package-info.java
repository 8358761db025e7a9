/**
 * What the three representation families share and nobody else may use: the immutable ordered
 * behavior set and the common part of an activation. Never reached from another module.
 */
@NullMarked
package org.armgals.representation.internal;

import org.jspecify.annotations.NullMarked;
