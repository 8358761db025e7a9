package org.armgals.examples.cli;

import java.io.PrintStream;
import java.util.List;
import org.armgals.examples.Demo;
import org.armgals.examples.run.Example;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;

/** The active-object demo, as {@code armgals run demo}. */
final class DemoExample implements Example {

  @Override
  public String name() {
    return "demo";
  }

  @Override
  public String summary() {
    return "active objects in both modes: a guarded buffer, futures, a reactive pair";
  }

  @Override
  public Summary run(RunSettings settings, PrintStream out) {
    Demo.Outcome outcome = Demo.run(out);
    return new Summary(
        List.of(
            new Summary.Entry("processed", Long.toString(outcome.stats().processed())),
            new Summary.Entry("handled failures", Long.toString(outcome.handledFailures())),
            new Summary.Entry("clean shutdown", Boolean.toString(outcome.cleanShutdown()))));
  }
}
