/**
 * The {@code armgals} command line: list the examples, run one (and watch it live in a browser),
 * replay a run from its trace, play it back in the browser, and write the skeleton of a new robot.
 * {@link org.armgals.examples.cli.Armgals#main} is the entry point of the {@code ./armgals}
 * launcher and of {@code java -jar examples.jar}.
 *
 * <p>Exit status: 0 when the command did what it was asked, 1 when a run failed or a replay did not
 * reproduce its trace, 2 when the command line was wrong (a bad option, an unknown example, a file
 * that is not a trace, a robot name that is not one), 130 when a run was interrupted (Ctrl-C: it
 * keeps what it had, its trace marked incomplete); the error is one line that says what to do.
 * Every command's {@code --help} lists them.
 */
@NullMarked
package org.armgals.examples.cli;

import org.jspecify.annotations.NullMarked;
