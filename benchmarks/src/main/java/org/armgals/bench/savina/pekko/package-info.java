/**
 * The Savina-style workloads written with Apache Pekko typed actors, the baseline: the default
 * dispatcher and mailbox, {@code AbstractBehavior} actors with receive builders (the style of
 * Pekko's Java documentation), {@code AskPattern} for answers to code outside the actor system. The
 * actors of one run are children of one root actor, so that closing the run stops them all.
 */
@NullMarked
package org.armgals.bench.savina.pekko;

import org.jspecify.annotations.NullMarked;
