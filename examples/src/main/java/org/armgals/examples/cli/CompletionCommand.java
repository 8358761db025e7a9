package org.armgals.examples.cli;

import java.io.PrintStream;
import picocli.AutoComplete;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code armgals completion}: prints the bash (and zsh) completion script of the whole command
 * line, picocli's {@link AutoComplete}: {@code source <(./armgals completion)}.
 */
@Command(
    name = "completion",
    mixinStandardHelpOptions = true,
    description = {
      "Prints the bash completion script of armgals' commands and options.",
      "Use it with: source <(./armgals completion)"
    })
final class CompletionCommand implements Runnable {
  private final PrintStream out;

  @Spec CommandSpec spec = CommandSpec.create();

  CompletionCommand(PrintStream out) {
    this.out = out;
  }

  @Override
  public void run() {
    out.print(AutoComplete.bash("armgals", spec.root().commandLine()));
    out.flush();
  }
}
