package org.armgals.examples.run;

import java.io.PrintStream;

/**
 * Something {@code armgals run <name>} can run: an example robot, or a demo of the runtime.
 *
 * <p>Implementations are stateless: {@link #run} may be called more than once, from any thread.
 */
public interface Example {

  /** The name on the command line: lower case letters and dashes. */
  String name();

  /** One line that says what it shows, for {@code armgals list}. */
  String summary();

  /**
   * Runs it with {@code settings}, telling what happens on {@code out}, and answers the lines of
   * its summary.
   *
   * @throws IllegalArgumentException if a setting does not apply, naming it and what would
   */
  Summary run(RunSettings settings, PrintStream out);
}
