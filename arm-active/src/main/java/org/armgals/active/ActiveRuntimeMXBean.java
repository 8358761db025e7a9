package org.armgals.active;

/**
 * The figures of a runtime over JMX, registered as {@code
 * org.armgals:type=ActiveRuntime,name="<runtime name>"}. See {@link RuntimeStats} for their
 * meaning.
 */
public interface ActiveRuntimeMXBean {
  /** The runtime's name. */
  String getName();

  /** Live objects. */
  long getObjects();

  /** Events waiting in all buffers. */
  long getQueuedEvents();

  /** The deepest buffer. */
  long getMaxQueueDepth();

  /** Events processed. */
  long getProcessed();

  /** Events dropped by full buffers. */
  long getDropped();

  /** Sends refused. */
  long getRejected();

  /** Failures while processing. */
  long getFailures();

  /** Late instants of the runtime's clocks. */
  long getOverruns();

  /** Events the transport handed to the broker. */
  long getTransportSent();

  /** Events the transport took from the broker. */
  long getTransportReceived();

  /** Transport messages that carried more than one event. */
  long getTransportBatches();

  /** Inbound transport messages rejected: the dead-letter count. */
  long getTransportRejected();

  /** Transport messages found missing by the gaps in their routes' sequence numbers. */
  long getTransportLost();

  /** Transport messages accepted but never handed to the broker. */
  long getTransportUnsent();

  /** Worker threads alive (more than the configured number while some are blocked). */
  int getWorkers();
}
