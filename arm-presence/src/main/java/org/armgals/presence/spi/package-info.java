/**
 * What users plug into a presence: the listener that hears runtimes join, leave and fall silent
 * (the kernel plugs in here to notify the behavioral meta-entities concerned).
 */
@NullMarked
package org.armgals.presence.spi;

import org.jspecify.annotations.NullMarked;
