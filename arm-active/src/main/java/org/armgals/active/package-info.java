/**
 * Active and reactive objects after the paper's {@code active} package (§4.1, §5.3).
 *
 * <p>An {@link org.armgals.active.ActiveObject} owns a servant, a bounded buffer of {@link
 * org.armgals.active.Event}s and, only while it has something to do, a virtual thread. It runs in
 * one of two {@link org.armgals.active.Mode}s chosen at creation: asynchronous (events one at a
 * time as they come) or synchronous (a {@link org.armgals.active.Clock} releases it once per
 * instant). Requests to it are sent through an {@link org.armgals.active.ActiveRef}; synchronized
 * requests answer with a {@link org.armgals.active.Future} or {@link
 * org.armgals.active.FutureValue} that waits by necessity. The {@link
 * org.armgals.active.ActiveRuntime} creates, counts and stops objects.
 *
 * <p>The concurrency contract of every type is in its javadoc and in {@code
 * docs/concurrency-contract.md}.
 */
@NullMarked
package org.armgals.active;

import org.jspecify.annotations.NullMarked;
