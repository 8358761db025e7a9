package org.armgals.examples.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * A run's outputs in the making: a hidden directory inside the output directory, whose files move
 * into the output directory (each replacing the file of that name, by a rename) when the run {@link
 * #keep keeps} them, and which is deleted with whatever is left in it when closed. So a run that
 * fails, at its start or later, leaves the previous run's files as they were; the output directory
 * itself is never deleted, but for an empty one this run made. Used by one thread.
 */
final class Staging implements AutoCloseable {
  private final Path out;
  private final Path dir;
  private final boolean made;

  private Staging(Path out, Path dir, boolean made) {
    this.out = out;
    this.dir = dir;
    this.made = made;
  }

  /**
   * A staging directory inside {@code out}, made with {@code out} if it is not there.
   *
   * @throws UncheckedIOException if either cannot be made, naming the directory
   */
  static Staging in(Path out) {
    boolean made = !Files.isDirectory(out);
    try {
      Files.createDirectories(out);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot create the output directory " + out, e);
    }
    try {
      return new Staging(out, Files.createTempDirectory(out, ".running-"), made);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write in the output directory " + out, e);
    }
  }

  /** Where the run writes. */
  Path dir() {
    return dir;
  }

  /**
   * Moves what the run wrote into the output directory.
   *
   * @throws UncheckedIOException if a file cannot be moved, naming it
   */
  void keep() {
    for (Path file : entries(dir)) {
      Path target = out.resolve(file.getFileName());
      try {
        Files.move(file, target, StandardCopyOption.REPLACE_EXISTING);
      } catch (IOException e) {
        throw new UncheckedIOException("cannot move " + file + " to " + target, e);
      }
    }
  }

  /**
   * Deletes the staging directory and what is left in it, and {@code out} if this made it empty.
   */
  @Override
  public void close() {
    try (Stream<Path> files = Files.walk(dir)) {
      for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
        Files.deleteIfExists(file);
      }
      if (made) {
        Files.deleteIfExists(out);
      }
    } catch (NoSuchFileException | DirectoryNotEmptyException e) {
      // Gone already, or the output directory holds files now: it stays.
    } catch (IOException e) {
      throw new UncheckedIOException("cannot delete " + dir, e);
    }
  }

  private static List<Path> entries(Path dir) {
    try (Stream<Path> files = Files.list(dir)) {
      return files.sorted().toList();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot list " + dir, e);
    }
  }
}
