package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * A data event that says who sent it and its rank among that sender's events: the stress tests tell
 * events apart by it. {@code thread} is the sending test thread, not an active object, so {@link
 * #sender()} is null.
 */
record Tagged(Address destination, int thread, int seq) implements Event {
  @Override
  public @Nullable Address sender() {
    return null;
  }
}
