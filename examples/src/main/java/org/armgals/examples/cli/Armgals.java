package org.armgals.examples.cli;

import static java.util.Objects.requireNonNull;

import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code armgals} command: {@code list}, {@code run <example>}, {@code replay <trace>}, {@code
 * new <name>}. See the package javadoc for the exit statuses.
 */
@Command(
    name = "armgals",
    mixinStandardHelpOptions = true,
    versionProvider = Armgals.Version.class,
    description = "Runs the armgals example robots and shows what they did.",
    subcommandsRepeatable = false)
public final class Armgals implements Runnable {
  /** The command line was wrong: a bad option or value, an unknown example. */
  public static final int USAGE = 2;

  /** A run failed. */
  public static final int FAILED = 1;

  private final PrintStream out;

  private Armgals(PrintStream out) {
    this.out = out;
  }

  /** The launcher's entry point: runs the command and exits with its status. */
  public static void main(String[] args) {
    System.exit(execute(Catalog.standard(), System.out, System.err, args));
  }

  /**
   * Runs the command {@code args} over {@code catalog}, printing on {@code out} and errors on
   * {@code err}, and answers its exit status.
   */
  public static int execute(Catalog catalog, PrintStream out, PrintStream err, String... args) {
    requireNonNull(catalog, "catalog");
    requireNonNull(out, "out");
    requireNonNull(err, "err");
    requireNonNull(args, "args");
    CommandLine line =
        new CommandLine(new Armgals(out))
            .addSubcommand(new ListCommand(catalog, out))
            .addSubcommand(new RunCommand(catalog, out))
            .addSubcommand(new ReplayCommand(catalog, out))
            .addSubcommand(new NewCommand(out));
    line.setOut(new PrintWriter(out, true, StandardCharsets.UTF_8));
    line.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
    line.setParameterExceptionHandler(
        (e, given) -> {
          err.println("armgals: " + e.getMessage() + " (try '" + helpOf(e) + "')");
          return USAGE;
        });
    line.setExecutionExceptionHandler(
        (e, commandLine, parsed) -> {
          if (e instanceof UsageException || e instanceof IllegalArgumentException) {
            err.println("armgals: " + e.getMessage());
            return USAGE;
          }
          err.println("armgals: the run failed: " + e);
          return FAILED;
        });
    return line.execute(args);
  }

  private static String helpOf(CommandLine.ParameterException e) {
    return e.getCommandLine().getCommandSpec().qualifiedName() + " --help";
  }

  /** Without a subcommand: print the usage. */
  @Override
  public void run() {
    new CommandLine(this).usage(out);
  }

  /** The version of the examples jar, from its manifest when there is one. */
  static final class Version implements CommandLine.IVersionProvider {
    @Override
    public String[] getVersion() {
      String version = Armgals.class.getPackage().getImplementationVersion();
      return new String[] {"armgals " + (version == null ? "(development build)" : version)};
    }
  }
}
