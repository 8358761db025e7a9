/**
 * What users plug into the kernel: the policy of a behavioral meta-entity ({@link
 * org.armgals.kernel.spi.MetaPolicy}) and what it may do from inside ({@link
 * org.armgals.kernel.spi.MetaContext}).
 */
@NullMarked
package org.armgals.kernel.spi;

import org.jspecify.annotations.NullMarked;
