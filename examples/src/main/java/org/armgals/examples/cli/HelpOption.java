package org.armgals.examples.cli;

import picocli.CommandLine.Option;

/** {@code -h}/{@code --help} of a subcommand: its usage, status 0, whatever else is missing. */
final class HelpOption {
  @Option(
      names = {"-h", "--help"},
      usageHelp = true,
      description = "Show this help message and exit.")
  boolean help;
}
