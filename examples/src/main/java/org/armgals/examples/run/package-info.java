/**
 * What a run of an example is, apart from the command line that starts it: an {@link
 * org.armgals.examples.run.Example}, the {@link org.armgals.examples.run.RunSettings} it runs with,
 * the {@link org.armgals.examples.run.Summary} it ends with, and {@link
 * org.armgals.examples.run.RunInterrupted} when Ctrl-C stops it. The robots, the simulation glue
 * and the command line all use this package; it uses none of them, so that the examples' packages
 * form no cycle.
 */
@NullMarked
package org.armgals.examples.run;

import org.jspecify.annotations.NullMarked;
