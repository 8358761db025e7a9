/**
 * The Savina-style workloads on the yardstick: actors written by hand, a {@code
 * ConcurrentLinkedQueue} mailbox each on a {@code ForkJoinPool}, one "scheduled" flag, batches of
 * 64 ({@link org.armgals.bench.savina.yardstick.Actor}, about 60 lines). It is what a user might
 * write instead of taking a library, untuned: a runtime that loses to it costs its users speed.
 * Messages are lambdas applied to the actor's state, as armgals' one-way sends are; answers to the
 * main thread come through a {@code CompletableFuture} completed by the actor. Mailboxes are
 * unbounded, as Pekko's default.
 */
@NullMarked
package org.armgals.bench.savina.yardstick;

import org.jspecify.annotations.NullMarked;
