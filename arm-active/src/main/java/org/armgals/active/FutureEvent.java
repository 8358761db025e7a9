package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * The reply to a synchronized request, delivered to a synchronous (reactive) object as an event
 * (paper §5.3, class {@code FutureEvent}). Taking it at a release makes the matching {@link
 * SynchronousFuture} available and, if the servant is an {@link EventProcessor}, hands it this
 * event (its guard is not asked: a reply is never held back). It is queued even when the buffer is
 * full: a reply the object asked for is never dropped.
 *
 * @param sender the object that processed the request
 * @param destination the object that sent the request and owns the future
 * @param requestId the number of the request in its sender
 * @param value the value, or {@code null} for a signal or a failure
 * @param failure the servant's exception, or {@code null} on success
 */
public record FutureEvent(
    Address sender,
    Address destination,
    long requestId,
    @Nullable Object value,
    @Nullable Throwable failure)
    implements Event {}
