package org.armgals.maam.spi;

import java.util.List;

/**
 * The neighbour messages that arrived since the previous cycle, in arrival order.
 *
 * @param messages copied, unmodifiable
 */
public record Inbox(List<NeighbourMessage> messages) {

  /** No message. */
  public static final Inbox EMPTY = new Inbox(List.of());

  /** Copies the list. */
  public Inbox {
    messages = List.copyOf(messages);
  }
}
