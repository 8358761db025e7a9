/**
 * Presence of runtimes on a broker: each runtime beats on a topic, and notices when another one
 * joins, leaves, or falls silent (its JVM was killed, its host or link went down). {@link
 * org.armgals.presence.Presence} is the facade; {@link org.armgals.presence.PresenceEvent} what its
 * listeners hear.
 */
@NullMarked
package org.armgals.presence;

import org.jspecify.annotations.NullMarked;
