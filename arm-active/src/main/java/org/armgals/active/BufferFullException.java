package org.armgals.active;

/**
 * An event could not be queued: the receiver's bounded buffer is full and its policy is {@link
 * OverflowPolicy#reject()}, or {@link OverflowPolicy#block} ran out of time; or a transport's
 * outbound queue is full under the same policies.
 */
public final class BufferFullException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** The buffer of {@code object}, of {@code capacity} events, is full. */
  public BufferFullException(Address object, int capacity, String detail) {
    super("buffer of " + object + " is full (capacity " + capacity + "): " + detail);
  }

  /**
   * A full buffer that is not an object's: a transport's outbound queue; {@code message} says
   * which.
   */
  public BufferFullException(String message) {
    super(message);
  }
}
