/**
 * The {@code armgals} command line: list the examples, run one, and (as the robots come) replay a
 * run and write a robot skeleton. {@link org.armgals.examples.cli.Armgals#main} is the entry point
 * of the {@code ./armgals} launcher and of {@code java -jar examples.jar}.
 *
 * <p>Exit status: 0 when the command did what it was asked, 1 when a run failed, 2 when the command
 * line was wrong (a bad option, an unknown example); the error is one line that says what to do.
 */
@NullMarked
package org.armgals.examples.cli;

import org.jspecify.annotations.NullMarked;
