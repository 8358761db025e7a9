package org.armgals.bench.gals;

import java.io.PrintStream;

/** One named benchmark of {@link Gals}: it prints its own {@code gals name=...} lines. */
interface GalsBenchmark {

  /** The name given on the command line and printed as {@code name=}. */
  String name();

  /**
   * Runs it.
   *
   * @param seconds how long each measured part runs (a benchmark may warm up as long again)
   */
  void run(int seconds, PrintStream out) throws Exception;
}
