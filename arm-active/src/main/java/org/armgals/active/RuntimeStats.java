package org.armgals.active;

/**
 * A snapshot of a runtime's figures, also published over JMX as the MBean {@code
 * org.armgals:type=ActiveRuntime,name="<runtime name>"} (quoted by {@code ObjectName.quote}).
 *
 * @param objects live objects
 * @param queuedEvents events waiting in all buffers
 * @param maxQueueDepth the deepest buffer now
 * @param processed events processed since the start (including failed ones)
 * @param dropped events dropped by a full buffer
 * @param rejected sends refused (full buffer with reject, block timeout, stopped object)
 * @param failures exceptions thrown while processing events or cycles
 * @param overruns instants of the runtime's clocks that ended late
 * @param transport the figures of the runtime's transport ({@link TransportStats#NONE} without one)
 */
public record RuntimeStats(
    long objects,
    long queuedEvents,
    long maxQueueDepth,
    long processed,
    long dropped,
    long rejected,
    long failures,
    long overruns,
    TransportStats transport) {}
