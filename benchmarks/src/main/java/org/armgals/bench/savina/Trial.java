package org.armgals.bench.savina;

/** One prepared run of a workload: {@link #run()} is timed, {@link #close()} is not. */
public interface Trial extends AutoCloseable {

  /**
   * Does the work, checks its result and returns how many operations it did.
   *
   * @throws IllegalStateException the result is wrong (the run fails loudly)
   */
  long run() throws Exception;

  /** Lets go of the run's objects. */
  @Override
  void close();
}
