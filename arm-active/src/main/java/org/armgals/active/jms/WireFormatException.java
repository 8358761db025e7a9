package org.armgals.active.jms;

/** A message that the wire codec refuses to decode; the runtime counts it as a dead letter. */
final class WireFormatException extends Exception {
  private static final long serialVersionUID = 1L;

  WireFormatException(String message) {
    super(message);
  }

  WireFormatException(String message, Throwable cause) {
    super(message, cause);
  }
}
