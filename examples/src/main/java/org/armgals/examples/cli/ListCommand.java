package org.armgals.examples.cli;

import java.io.PrintStream;
import org.armgals.examples.run.Example;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/** {@code armgals list}: the examples, one line each. */
@Command(name = "list", description = "Lists the example robots, one line each.")
final class ListCommand implements Runnable {
  @Mixin HelpOption help = new HelpOption();

  private final Catalog catalog;
  private final PrintStream out;

  ListCommand(Catalog catalog, PrintStream out) {
    this.catalog = catalog;
    this.out = out;
  }

  @Override
  public void run() {
    int width = catalog.all().stream().mapToInt(e -> e.name().length()).max().orElse(0);
    for (Example example : catalog.all()) {
      out.printf("%-" + width + "s  %s%n", example.name(), example.summary());
    }
  }
}
