package org.armgals.examples.cli;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.armgals.examples.run.Example;
import org.armgals.examples.sim.Replay;

/**
 * A trace that {@code armgals run} wrote, read for a command ({@code replay}, {@code view}): its
 * text, its header and the example that wrote it. What is wrong with the file is a usage error that
 * names it.
 *
 * @param file the trace
 * @param text all of it
 * @param header its first line
 * @param example the example of this armgals that wrote it
 */
record TraceFile(Path file, String text, Replay.Header header, Example example) {

  /** The trace's name in a run's output directory. */
  static final String TRACE = "trace.jsonl";

  /**
   * Reads {@code given}, a trace or the output directory of a run that holds one, and finds its
   * example in {@code catalog}.
   *
   * @throws UsageException the file cannot be read, is not a trace, or is a trace of an example
   *     that {@code catalog} does not have; the directory holds no trace
   */
  static TraceFile read(Path given, Catalog catalog) {
    Path file = Files.isDirectory(given) ? given.resolve(TRACE) : given;
    if (Files.isDirectory(given) && !Files.exists(file)) {
      throw new UsageException(
          "no trace in " + given + ": expected the output directory of 'armgals run'");
    }
    String text = text(file);
    Replay.Header header;
    try {
      header = Replay.Header.parse(text.lines().findFirst().orElse(""));
    } catch (IllegalArgumentException e) {
      throw new UsageException(file + ": " + e.getMessage());
    }
    Example example =
        catalog
            .find(header.example())
            .orElseThrow(
                () ->
                    new UsageException(
                        file
                            + " is a trace of example '"
                            + header.example()
                            + "', which this armgals does not have; 'armgals list' shows those it"
                            + " has"));
    return new TraceFile(file, text, header, example);
  }

  private static String text(Path trace) {
    try {
      return Files.readString(trace, StandardCharsets.UTF_8);
    } catch (NoSuchFileException e) {
      throw new UsageException("no trace at " + trace + "; 'armgals run' leaves one in its --out");
    } catch (CharacterCodingException e) {
      throw new UsageException(trace + ": not an armgals trace: it is not UTF-8 text");
    } catch (IOException e) {
      throw new UsageException("cannot read " + trace + ": " + e);
    }
  }
}
