package org.armgals.active;

import org.jspecify.annotations.Nullable;

/** A future the runtime hands to a sender and completes from the receiver. */
sealed interface ReplyFuture<R extends @Nullable Object> extends FutureValue<R>, Reply<R>
    permits ValueFuture, SyncFuture {}
