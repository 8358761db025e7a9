/**
 * What users and later modules plug into the active-object runtime: the {@link
 * org.armgals.active.spi.ErrorHandler} of a runtime, the {@link
 * org.armgals.active.spi.ObjectListener} of an object (the behavioral meta-entity, later), and the
 * {@link org.armgals.active.spi.Transport} that carries events between runtimes, and what a
 * transport offers the modules above it without naming itself: the {@link
 * org.armgals.active.spi.RemoteAnswer} futures it completes, its {@link
 * org.armgals.active.spi.NameService}, the {@link org.armgals.active.spi.AllowList} of the types it
 * carries, and the {@link org.armgals.active.spi.PresenceListener}s that hear runtimes join, leave
 * and fall silent. Two ways of waiting, shared by the runtime and the modules above it: the {@link
 * org.armgals.active.spi.DeadlinePacer} that waits for a point in time (the real-time clocks, the
 * islands' runners, the simulator's pacer), and the {@link org.armgals.active.spi.IdleStrategy} of
 * a loop that waits for work ({@link org.armgals.active.spi.BackoffIdleStrategy}: spin, yield, then
 * park).
 */
@NullMarked
package org.armgals.active.spi;

import org.jspecify.annotations.NullMarked;
