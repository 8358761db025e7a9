package org.armgals.examples.cli;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.examples.run.RunInterrupted;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * The {@code armgals} command: {@code list}, {@code run <example>}, {@code replay <trace>}, {@code
 * view <trace>}, {@code new <name>}, {@code completion} and {@code help}. See the package javadoc
 * for the exit statuses.
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

  /** A run failed, or a replay did not reproduce its trace. */
  public static final int FAILED = 1;

  /** The run was interrupted (Ctrl-C): 128 + SIGINT, as a shell reports it. */
  public static final int INTERRUPTED = 130;

  /** The exit statuses, as every command's {@code --help} lists them. */
  private static final Map<String, String> EXIT_CODES = exitCodes();

  private final PrintStream out;

  @Spec CommandSpec spec = CommandSpec.create();

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
            .addSubcommand(new ViewCommand(catalog, out))
            .addSubcommand(new NewCommand(out))
            .addSubcommand(new CompletionCommand(out))
            .addSubcommand(new CommandLine.HelpCommand());
    document(line);
    line.setOut(new PrintWriter(out, true, StandardCharsets.UTF_8));
    line.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
    line.setParameterExceptionHandler(
        (e, given) -> {
          err.println("armgals: " + e.getMessage() + suggestion(e) + " (try '" + helpOf(e) + "')");
          return USAGE;
        });
    line.setExecutionExceptionHandler(
        (e, commandLine, parsed) -> {
          if (e instanceof RunInterrupted) {
            return INTERRUPTED; // the run has said so, and the JVM may be ending
          }
          if (e instanceof UsageException || e instanceof IllegalArgumentException) {
            err.println("armgals: " + e.getMessage());
            return USAGE;
          }
          if (e instanceof UncheckedIOException io) {
            err.println("armgals: " + io.getMessage() + ": " + reason(io.getCause()));
            return FAILED;
          }
          err.println("armgals: the run failed: " + e);
          return FAILED;
        });
    return line.execute(args);
  }

  /** Gives {@code line} and each of its subcommands the exit statuses in their help. */
  private static void document(CommandLine line) {
    line.getCommandSpec()
        .usageMessage()
        .exitCodeListHeading("%nExit status:%n")
        .exitCodeList(EXIT_CODES);
    line.getSubcommands().values().forEach(Armgals::document);
  }

  private static Map<String, String> exitCodes() {
    Map<String, String> codes = new LinkedHashMap<>();
    codes.put("  0", "done");
    codes.put("  1", "a run failed, or a replay did not reproduce its trace");
    codes.put("  2", "the command line was wrong (a bad option or value, an unknown name)");
    codes.put(
        INTERRUPTED + "", "interrupted (Ctrl-C): the run keeps what it has, its trace marked so");
    return Collections.unmodifiableMap(codes);
  }

  private static String helpOf(CommandLine.ParameterException e) {
    return e.getCommandLine().getCommandSpec().qualifiedName() + " --help";
  }

  /**
   * What the user may have meant by an unknown option or command: the option or command at most two
   * edits (a letter added, dropped, changed, or two swapped) from the first unmatched word, or else
   * picocli's suggestion, if there is one.
   */
  private static String suggestion(CommandLine.ParameterException e) {
    if (!(e instanceof CommandLine.UnmatchedArgumentException unmatched)) {
      return "";
    }
    List<String> names = new ArrayList<>();
    String word = unmatched.getUnmatched().isEmpty() ? "" : unmatched.getUnmatched().get(0);
    CommandSpec spec = e.getCommandLine().getCommandSpec();
    if (word.startsWith("-")) {
      spec.options().forEach(o -> names.addAll(List.of(o.names())));
    } else {
      names.addAll(spec.subcommands().keySet());
    }
    return names.stream()
        .filter(name -> edits(word, name) <= 2)
        .min(Comparator.comparingInt(name -> edits(word, name)))
        .or(() -> unmatched.getSuggestions().stream().findFirst())
        .map(name -> "; did you mean '" + name + "'?")
        .orElse("");
  }

  /** The optimal string alignment distance between {@code a} and {@code b}. */
  static int edits(String a, String b) {
    int[][] d = new int[a.length() + 1][b.length() + 1];
    for (int i = 0; i <= a.length(); i++) {
      for (int j = 0; j <= b.length(); j++) {
        if (i == 0 || j == 0) {
          d[i][j] = i + j;
          continue;
        }
        int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
        d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
        if (i > 1
            && j > 1
            && a.charAt(i - 1) == b.charAt(j - 2)
            && a.charAt(i - 2) == b.charAt(j - 1)) {
          d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
        }
      }
    }
    return d[a.length()][b.length()];
  }

  /**
   * Why an I/O operation failed, as the operating system said it ("Permission denied", "Not a
   * directory", "No space left on device"), for a message that names the file itself.
   */
  static String reason(IOException e) {
    if (e instanceof FileSystemException f) {
      if (f.getReason() != null) {
        return f.getReason();
      }
      return switch (f) {
        case AccessDeniedException a -> "Permission denied";
        case NoSuchFileException n -> "No such file or directory";
        case FileAlreadyExistsException x -> "File exists";
        case NotDirectoryException d -> "Not a directory";
        case DirectoryNotEmptyException d -> "Directory not empty";
        default -> f.getClass().getSimpleName();
      };
    }
    return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
  }

  /** Without a subcommand: the usage, with the list of commands. */
  @Override
  public void run() {
    spec.commandLine().usage(out);
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
