package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.time.format.DateTimeParseException;

/**
 * What a bounded buffer does with an event that arrives when it is full (paper §4.1, {@code
 * BoundedBuffer}). Every dropped event is counted by the runtime and reported to the receiver's
 * {@link org.armgals.active.spi.ObjectListener}; a dropped synchronized request fails its future.
 */
public sealed interface OverflowPolicy {

  /**
   * The sender waits for room, up to {@code timeout}, then gets a {@link BufferFullException}. Not
   * allowed for synchronous (reactive) objects: a reactive object never blocks its sender.
   */
  record Block(Duration timeout) implements OverflowPolicy {
    /** Checks the timeout. */
    public Block {
      requireNonNull(timeout, "timeout");
      if (timeout.isNegative()) {
        throw new IllegalArgumentException("timeout must be >= 0, was " + timeout);
      }
    }
  }

  /** The sender gets a {@link BufferFullException} at once. */
  record Reject() implements OverflowPolicy {}

  /** The arriving event is dropped. */
  record DropNewest() implements OverflowPolicy {}

  /** The oldest queued event is dropped to make room for the arriving one. */
  record DropOldest() implements OverflowPolicy {}

  /** Block the sender up to {@code timeout}. */
  static OverflowPolicy block(Duration timeout) {
    return new Block(timeout);
  }

  /** Reject with an exception. */
  static OverflowPolicy reject() {
    return new Reject();
  }

  /** Drop the arriving event. */
  static OverflowPolicy dropNewest() {
    return new DropNewest();
  }

  /** Drop the oldest queued event. */
  static OverflowPolicy dropOldest() {
    return new DropOldest();
  }

  /**
   * Reads a policy from configuration text: {@code reject}, {@code drop-newest}, {@code
   * drop-oldest}, or {@code block:<ISO-8601 duration>} such as {@code block:PT5S}.
   *
   * @throws IllegalArgumentException naming the text and the expected forms
   */
  static OverflowPolicy parse(String text) {
    requireNonNull(text, "text");
    String expected = "expected reject, drop-newest, drop-oldest or block:<duration> (block:PT5S)";
    return switch (text) {
      case "reject" -> reject();
      case "drop-newest" -> dropNewest();
      case "drop-oldest" -> dropOldest();
      default -> {
        if (!text.startsWith("block:")) {
          throw new IllegalArgumentException("unknown overflow policy '" + text + "'; " + expected);
        }
        try {
          yield block(Duration.parse(text.substring("block:".length())));
        } catch (DateTimeParseException e) {
          throw new IllegalArgumentException(
              "bad duration in overflow policy '" + text + "'; " + expected, e);
        }
      }
    };
  }
}
