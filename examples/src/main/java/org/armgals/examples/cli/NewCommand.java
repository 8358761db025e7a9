package org.armgals.examples.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.lang.model.SourceVersion;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code armgals new <name>}: writes the skeleton of a robot, a small Maven project whose sources
 * follow the four steps of §5.4 (signals, modules, a robot class that registers its schemas and
 * says what it shows its meta level) and figure 8 (the robot's kind with a catalog, a behavioral
 * meta level, and a simulated example with a {@code main} that runs the robot as a kernel entity
 * with its meta level in its JVM or in another), with JUnit 5 tests that the robot crawls and that
 * its meta level adapts it, and armgals' own Maven wrapper; it builds, passes its tests and runs as
 * written, formatted as armgals' sources are. The templates are resources next to this class
 * ({@code skeleton/*.tmpl}); their placeholders are {@code ${name}}, {@code ${Name}}, {@code
 * ${package}}, {@code ${version}} (the version of armgals that writes them) and {@code ${junit}}.
 * It refuses to write inside an armgals checkout, whose build takes every {@code src} directory
 * below it for its own.
 */
@Command(
    name = "new",
    description = "Writes the skeleton of a new robot, ready to compile and run.")
final class NewCommand implements Callable<Integer> {
  @Mixin HelpOption help = new HelpOption();

  static final Pattern NAME = Pattern.compile("[a-z][a-z0-9]{0,19}");

  /** What the root POM of an armgals checkout says it is. */
  private static final String PARENT_ARTIFACT = "<artifactId>armgals-parent</artifactId>";

  private static final Pattern PLACEHOLDER = Pattern.compile("\\$\\{(\\w+)}");

  /** The lines that mark the regions docs/user-guide.md shows; a skeleton goes without them. */
  private static final Pattern TAG_LINE =
      Pattern.compile("(?m)^[ \\t]*// (tag|end)::[\\w.-]+\\[]\\R");

  /**
   * Template, and where it goes: {@code JAVA/} for the package's source directory, {@code
   * RESOURCES/} for the main resources, {@code TEST/} for the package's test directory.
   */
  private static final List<String[]> FILES =
      List.of(
          new String[] {"pom.xml.tmpl", "pom.xml"},
          new String[] {"README.md.tmpl", "README.md"},
          new String[] {"Signals.java.tmpl", "JAVA/Signals.java"},
          new String[] {"Modules.java.tmpl", "JAVA/Modules.java"},
          new String[] {"Robot.java.tmpl", "JAVA/${Name}Robot.java"},
          new String[] {"Meta.java.tmpl", "JAVA/${Name}Meta.java"},
          new String[] {"Example.java.tmpl", "JAVA/${Name}Example.java"},
          new String[] {
            "SimExample.services.tmpl",
            "RESOURCES/META-INF/services/org.armgals.examples.sim.SimExample"
          },
          new String[] {"RobotTest.java.tmpl", "TEST/${Name}RobotTest.java"});

  /** The Maven wrapper, copied as it is (the build puts armgals' own beside the templates). */
  private static final List<String> WRAPPER =
      List.of("mvnw", "mvnw.cmd", ".mvn/wrapper/maven-wrapper.properties");

  private final PrintStream out;

  @Parameters(
      index = "0",
      paramLabel = "<name>",
      description = "the robot's name: a lower-case letter, then lower-case letters or digits")
  String name = "";

  @Option(
      names = "--dir",
      paramLabel = "<dir>",
      description = "where to write it (default: ./<name>); must not exist")
  Path dir;

  NewCommand(PrintStream out) {
    this.out = out;
  }

  @Override
  public Integer call() {
    Path target = dir == null ? Path.of(name) : dir;
    List<Path> written = write(name, target, version());
    out.println("wrote the robot '" + name + "' in " + target + ":");
    for (Path file : written) {
      out.println("  " + target.relativize(file));
    }
    out.println(
        "build, test and run it: cd "
            + target
            + " && ./mvnw -q verify exec:java   (see its README.md; docs/user-guide.md of"
            + " armgals)");
    return 0;
  }

  /**
   * Writes the skeleton of robot {@code name} into the new directory {@code target} and answers the
   * files written.
   *
   * @throws UsageException if the name is not one, or {@code target} exists
   */
  static List<Path> write(String name, Path target, String version) {
    check(name);
    if (Files.exists(target)) {
      throw new UsageException(
          target + " already exists; give another name, or another place with --dir");
    }
    checkout(target)
        .ifPresent(
            root -> {
              throw new UsageException(
                  target
                      + " is inside the armgals checkout "
                      + root
                      + ", whose build would take it for one of its own; write it elsewhere,"
                      + " say --dir "
                      + root.resolveSibling(name));
            });
    String upper = name.substring(0, 1).toUpperCase(Locale.ROOT) + name.substring(1);
    Map<String, String> values =
        Map.of(
            "name",
            name,
            "Name",
            upper,
            "package",
            name,
            "version",
            version,
            "junit",
            built("junit"));
    Path sources = target.resolve("src/main/java").resolve(name);
    Path resources = target.resolve("src/main/resources");
    Path tests = target.resolve("src/test/java").resolve(name);
    try {
      Files.createDirectories(sources);
      Files.createDirectories(tests);
      List<Path> written = new java.util.ArrayList<>();
      for (String[] file : FILES) {
        String place = fill(file[1], values);
        Path path =
            placed(
                place, target, Map.of("JAVA/", sources, "RESOURCES/", resources, "TEST/", tests));
        Files.createDirectories(path.getParent());
        String text =
            TAG_LINE.matcher(new String(template(file[0]), StandardCharsets.UTF_8)).replaceAll("");
        Files.writeString(path, fill(text, values), StandardCharsets.UTF_8);
        written.add(path);
      }
      for (String file : WRAPPER) {
        Path path = target.resolve(file);
        Files.createDirectories(path.getParent());
        Files.write(path, template("wrapper/" + file));
        if (file.equals("mvnw")) {
          executable(path);
        }
        written.add(path);
      }
      return List.copyOf(written);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write the skeleton in " + target, e);
    }
  }

  /** Where {@code place} goes: under the directory its prefix names, or under {@code target}. */
  private static Path placed(String place, Path target, Map<String, Path> directories) {
    for (Map.Entry<String, Path> d : directories.entrySet()) {
      if (place.startsWith(d.getKey())) {
        return d.getValue().resolve(place.substring(d.getKey().length()));
      }
    }
    return target.resolve(place);
  }

  /** The armgals checkout {@code target} would be in, if any: the nearest with armgals' POM. */
  static Optional<Path> checkout(Path target) {
    for (Path dir = target.toAbsolutePath().normalize(); dir != null; dir = dir.getParent()) {
      Path pom = dir.resolve("pom.xml");
      try {
        if (Files.isRegularFile(pom)
            && Files.readString(pom, StandardCharsets.UTF_8).contains(PARENT_ARTIFACT)) {
          return Optional.of(dir);
        }
      } catch (IOException e) {
        // An unreadable POM is not armgals' own: the checkout's is readable, it was built from.
      }
    }
    return Optional.empty();
  }

  private static void check(String name) {
    if (!NAME.matcher(name).matches()) {
      throw new UsageException(
          "'"
              + name
              + "' is not a robot name: a lower-case letter, then up to 19 lower-case letters or"
              + " digits (it names the robot, its Java package and its directory)");
    }
    if (SourceVersion.isKeyword(name)) {
      throw new UsageException("'" + name + "' is a Java keyword; choose another robot name");
    }
  }

  /** The version of armgals, as the build wrote it into {@code version.properties}. */
  static String version() {
    return built("version");
  }

  /** Makes {@code file} executable by whoever may read it, where the file system says so. */
  private static void executable(Path file) throws IOException {
    if (Files.getFileStore(file).supportsFileAttributeView("posix")) {
      Set<PosixFilePermission> permissions = new HashSet<>(Files.getPosixFilePermissions(file));
      permissions.add(PosixFilePermission.OWNER_EXECUTE);
      if (permissions.contains(PosixFilePermission.GROUP_READ)) {
        permissions.add(PosixFilePermission.GROUP_EXECUTE);
      }
      if (permissions.contains(PosixFilePermission.OTHERS_READ)) {
        permissions.add(PosixFilePermission.OTHERS_EXECUTE);
      }
      Files.setPosixFilePermissions(file, permissions);
    }
  }

  /**
   * A version the build wrote into {@code version.properties}: {@code version}, armgals' own, or
   * {@code junit}, the JUnit a skeleton's test runs on.
   */
  static String built(String key) {
    Properties properties = new Properties();
    try (InputStream in = NewCommand.class.getResourceAsStream("version.properties")) {
      if (in == null) {
        throw new IllegalStateException("version.properties is missing from the armgals jar");
      }
      properties.load(in);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read version.properties", e);
    }
    String version = properties.getProperty(key, "");
    if (version.isEmpty() || version.contains("${")) {
      throw new IllegalStateException(
          "version.properties was not filled in by the build: no " + key);
    }
    return version;
  }

  private static byte[] template(String file) throws IOException {
    try (InputStream in = NewCommand.class.getResourceAsStream("skeleton/" + file)) {
      if (in == null) {
        throw new IllegalStateException("the template skeleton/" + file + " is missing");
      }
      return in.readAllBytes();
    }
  }

  /** {@code text} with each known {@code ${key}} replaced; unknown ones (Maven's) stay. */
  static String fill(String text, Map<String, String> values) {
    Matcher m = PLACEHOLDER.matcher(text);
    StringBuilder b = new StringBuilder();
    while (m.find()) {
      String value = values.get(m.group(1));
      m.appendReplacement(b, Matcher.quoteReplacement(value == null ? m.group() : value));
    }
    m.appendTail(b);
    return b.toString();
  }
}
