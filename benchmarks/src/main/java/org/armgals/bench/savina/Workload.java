package org.armgals.bench.savina;

/** One workload of the suite, written for one implementation. */
@FunctionalInterface
public interface Workload {

  /** Builds what one run needs (objects and references to them); not timed. */
  Trial prepare() throws Exception;
}
