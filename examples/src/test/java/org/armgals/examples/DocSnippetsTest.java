package org.armgals.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Docs compile (docs/architecture.md, convention 10): every Java block in README.md and docs/ is
 * preceded by {@code <!-- snippet: path/To/File.java#name -->} and equals, up to whitespace, the
 * region between {@code // tag::name[]} and {@code // end::name[]} in that file (path from the
 * repository root).
 *
 * <p>To rewrite the blocks from the sources after changing an example: {@code ./mvnw -pl examples
 * -am test -Dtest=DocSnippetsTest -Dsurefire.failIfNoSpecifiedTests=false -Dsnippets.update=true}.
 */
class DocSnippetsTest {
  static final Pattern MARKER = Pattern.compile("<!--\\s*snippet:\\s*(\\S+?)#(\\S+?)\\s*-->");
  static final Pattern TAG = Pattern.compile("//\\s*(tag|end)::([\\w.-]+)\\[\\]");

  /** One fenced block in a Markdown file: its language, lines [open, close], and its marker. */
  record Block(Path doc, int open, int close, String language, Matcher marker) {
    String where() {
      return doc.getFileName() + ":" + (open + 1);
    }
  }

  @Test
  void everyJavaBlockInTheDocsIsTakenFromACompiledExample() {
    Path root = repositoryRoot();
    boolean update = Boolean.getBoolean("snippets.update");
    List<String> problems = new ArrayList<>();
    int checked = 0;
    for (Path doc : markdownFiles(root)) {
      List<String> lines = read(doc);
      List<String> rewritten = new ArrayList<>(lines);
      List<Block> blocks = blocks(doc, lines);
      // Replace from the bottom so that line numbers above stay valid.
      for (int i = blocks.size() - 1; i >= 0; i--) {
        Block b = blocks.get(i);
        if (b.marker() == null) {
          if (b.language().equals("java")) {
            problems.add(b.where() + ": a java block without a <!-- snippet: file#tag --> marker");
          }
          continue;
        }
        Path source = root.resolve(b.marker().group(1));
        String tag = b.marker().group(2);
        List<String> region;
        try {
          region = region(source, tag);
        } catch (IllegalArgumentException e) {
          problems.add(b.where() + ": " + e.getMessage());
          continue;
        }
        List<String> shown = lines.subList(b.open() + 1, b.close());
        checked++;
        if (!normalize(shown).equals(normalize(region))) {
          problems.add(
              b.where()
                  + ": differs from "
                  + b.marker().group(1)
                  + "#"
                  + tag
                  + "; expected:\n"
                  + String.join("\n", region));
          if (update) {
            for (int k = b.close() - 1; k > b.open(); k--) {
              rewritten.remove(k);
            }
            rewritten.addAll(b.open() + 1, region);
          }
        }
      }
      if (update && !rewritten.equals(lines)) {
        write(doc, rewritten);
      }
    }
    assertThat(problems).as("snippet problems (checked %d blocks)", checked).isEmpty();
    assertThat(checked).as("snippets found in README.md and docs/").isPositive();
  }

  @Test
  void regionExtractionDropsNestedTagLinesAndDedents() throws IOException {
    Path file = Files.createTempFile("Snippet", ".java");
    try {
      Files.writeString(
          file,
          """
          class X {
            // tag::outer[]
            void a() {
              // tag::inner[]
              b();
              // end::inner[]
            }
            // end::outer[]
          }
          """);
      assertThat(region(file, "outer")).containsExactly("void a() {", "  b();", "}");
      assertThat(region(file, "inner")).containsExactly("b();");
      assertThat(normalize(List.of("  void  a() {", "", "}  "))).containsExactly("void a() {", "}");
    } finally {
      Files.delete(file);
    }
  }

  /** The fenced blocks of a Markdown file, each with the marker right before it, if any. */
  static List<Block> blocks(Path doc, List<String> lines) {
    List<Block> blocks = new ArrayList<>();
    for (int i = 0; i < lines.size(); i++) {
      String line = lines.get(i).strip();
      if (!line.startsWith("```")) {
        continue;
      }
      String language = line.substring(3).strip();
      int close = i + 1;
      while (close < lines.size() && !lines.get(close).strip().equals("```")) {
        close++;
      }
      Matcher marker = null;
      int before = i - 1;
      while (before >= 0 && lines.get(before).isBlank()) {
        before--;
      }
      if (before >= 0) {
        Matcher m = MARKER.matcher(lines.get(before));
        if (m.find()) {
          marker = m;
        }
      }
      blocks.add(new Block(doc, i, close, language, marker));
      i = close;
    }
    return blocks;
  }

  /** The lines between {@code // tag::name[]} and {@code // end::name[]}, dedented. */
  static List<String> region(Path source, String tag) {
    if (!Files.isRegularFile(source)) {
      throw new IllegalArgumentException("no such file " + source);
    }
    List<String> lines = read(source);
    int start = -1;
    int end = -1;
    for (int i = 0; i < lines.size(); i++) {
      Matcher m = TAG.matcher(lines.get(i));
      if (m.find() && m.group(2).equals(tag)) {
        if (m.group(1).equals("tag")) {
          if (start >= 0) {
            throw new IllegalArgumentException("tag " + tag + " opens twice in " + source);
          }
          start = i;
        } else {
          end = i;
        }
      }
    }
    if (start < 0 || end < start) {
      throw new IllegalArgumentException(
          "no region tag::" + tag + "[] ... end::" + tag + "[] in " + source);
    }
    List<String> region = new ArrayList<>();
    for (String l : lines.subList(start + 1, end)) {
      if (!TAG.matcher(l).find()) {
        region.add(l.stripTrailing());
      }
    }
    while (!region.isEmpty() && region.get(region.size() - 1).isBlank()) {
      region.remove(region.size() - 1);
    }
    int indent =
        region.stream()
            .filter(l -> !l.isBlank())
            .mapToInt(l -> l.length() - l.stripLeading().length())
            .min()
            .orElse(0);
    return region.stream().map(l -> l.isBlank() ? "" : l.substring(indent)).toList();
  }

  /** Whitespace-insensitive form: each line trimmed, runs of blanks collapsed, empty lines gone. */
  static List<String> normalize(List<String> lines) {
    return lines.stream()
        .map(l -> l.strip().replaceAll("\\s+", " "))
        .filter(l -> !l.isEmpty())
        .toList();
  }

  static List<Path> markdownFiles(Path root) {
    List<Path> files = new ArrayList<>();
    files.add(root.resolve("README.md"));
    try (Stream<Path> docs = Files.walk(root.resolve("docs"))) {
      docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(files::add);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    return files;
  }

  /** The reactor root: the first directory up from here that has docs/ and README.md. */
  static Path repositoryRoot() {
    for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
      if (Files.isDirectory(p.resolve("docs")) && Files.isRegularFile(p.resolve("README.md"))) {
        return p;
      }
    }
    throw new IllegalStateException("no directory with docs/ and README.md above " + Path.of(""));
  }

  private static List<String> read(Path p) {
    try {
      return Files.readAllLines(p, StandardCharsets.UTF_8);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  private static void write(Path p, List<String> lines) {
    try {
      Files.writeString(p, String.join("\n", lines) + "\n", StandardCharsets.UTF_8);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }
}
