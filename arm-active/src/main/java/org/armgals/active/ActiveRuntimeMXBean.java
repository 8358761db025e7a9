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

  /** Worker threads alive (more than the configured number while some are blocked). */
  int getWorkers();
}
