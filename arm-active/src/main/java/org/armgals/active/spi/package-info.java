/**
 * What users and later modules plug into the active-object runtime: the {@link
 * org.armgals.active.spi.ErrorHandler} of a runtime, the {@link
 * org.armgals.active.spi.ObjectListener} of an object (the behavioral meta-entity, later), and the
 * {@link org.armgals.active.spi.Transport} that carries events between runtimes.
 */
@NullMarked
package org.armgals.active.spi;

import org.jspecify.annotations.NullMarked;
