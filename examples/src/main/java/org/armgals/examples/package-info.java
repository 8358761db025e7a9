/**
 * Runnable examples of armgals. {@link org.armgals.examples.Demo} is the project's {@code run}
 * command for now: a guarded bounded buffer, asynchronous objects exchanging requests with futures,
 * and two reactive objects on a manual clock. The how-to snippets quoted in the documentation live
 * in {@code org.armgals.examples.howto}.
 */
@NullMarked
package org.armgals.examples;

import org.jspecify.annotations.NullMarked;
