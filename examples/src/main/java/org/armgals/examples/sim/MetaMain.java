package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.active.jms.JmsTransport;
import org.armgals.active.jms.Presence;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.StructuralMeta;
import org.armgals.representation.p.PState;

/**
 * The main class of a meta level's own JVM ({@code armgals run <robot> --meta remote}): joins the
 * broker, makes the example's {@link MetaLevel} in a kernel of its own (the same code as in the
 * robots' JVM), takes every robot it watches by name through the broker's name service, says it is
 * ready (a file), and reflects on them until its standard input ends. Its standard input then says,
 * one line per robot ({@code <robot> <instant>}), the last instant each robot ran: in lock step it
 * waits until it has answered them all, so that its record is complete, writes its side of the
 * loop's record and its figures, and leaves.
 *
 * <p>Arguments: see {@link #args}.
 */
public final class MetaMain {
  /** How long it waits, at the end, for the answers to the robots' last instants. */
  static final Duration SETTLE = Duration.ofSeconds(30);

  private MetaMain() {}

  /** The arguments of a meta level's JVM for a run of {@code example} with {@code settings}. */
  static List<String> args(String example, String url, String prefix, RunSettings settings) {
    return List.of(
        example,
        url,
        prefix,
        settings.out().toAbsolutePath().toString(),
        Long.toString(settings.period().toNanos()),
        Long.toString(settings.seed()),
        settings.atoms().map(String::valueOf).orElse("-"),
        Boolean.toString(settings.realTime()));
  }

  /** Runs the meta level of a run; exits 2 on bad arguments. */
  public static void main(String[] args) throws IOException {
    if (args.length != 8) {
      System.err.println("expected 8 arguments (see MetaMain.args), got " + args.length);
      System.exit(2);
    }
    String example = args[0];
    String url = args[1];
    String prefix = args[2];
    Path out = Path.of(args[3]);
    RunSettings settings =
        new RunSettings(
            OptionalLong.empty(),
            Optional.empty(),
            Duration.ofNanos(Long.parseLong(args[4])),
            Long.parseLong(args[5]),
            args[6].equals("-") ? Optional.empty() : Optional.of(Integer.parseInt(args[6])),
            Boolean.parseBoolean(args[7]),
            Optional.empty(),
            out,
            RunSettings.MetaPlace.REMOTE);
    SimExample sim =
        find(example)
            .orElseThrow(() -> new IllegalArgumentException("no example named '" + example + "'"));
    MetaLevel level =
        sim.metaLevel(settings)
            .orElseThrow(() -> new IllegalArgumentException(example + " has no meta level"));
    String name = "meta-" + ProcessHandle.current().pid();
    BrokerLogin login = BrokerLogin.fromEnvironment();
    LoopRecorder recorder =
        new LoopRecorder(settings.period().toNanos(), null, org.armgals.active.TimeSource.system());
    try (JmsTransport transport =
        Kernel.allowKernelEvents(login.on(JmsTransport.builder().prefix(prefix), url)).build()) {
      ActiveRuntime runtime =
          ActiveRuntime.builder().name(name).workers(2).jmx(false).transport(transport).build();
      Kernel kernel =
          org.armgals.kernel.StructuralMeta.bootstrap(
              runtime, KernelOptions.defaults().withJmx(true).withListener(recorder));
      Presence presence =
          login
              .on(Presence.builder(), url)
              .prefix(prefix)
              .runtime(name)
              .listener(kernel.presenceListener())
              .failRequestsOf(transport)
              .build();
      try {
        Map<String, StructuralMeta<PState>> kinds = level.kinds(kernel);
        Map<String, String> metaOf = new LinkedHashMap<>();
        List<MetaLevel.Watch> watches =
            level.watches(
                (robot, nanos, text) -> recorder.note(metaOf.get(robot), robot, nanos, text));
        for (MetaLevel.Watch w : watches) {
          recorder.watchMeta(w.meta().name());
          w.meta().start(kernel);
          for (String robot : w.robots()) {
            metaOf.put(robot, w.meta().name());
            recorder.watch(robot);
            Entity remote = kernel.lookupRemote(transport, robot, kinds.get(robot));
            w.meta().addBaseLevelEntity(remote).touch();
            w.meta().setFilter(remote, w.filter()).touch();
          }
        }
        Files.writeString(out.resolve(Reflection.META_READY), name + "\n");
        System.out.println(
            "meta level of " + example + " takes " + metaOf.keySet() + " as " + name);
        Map<String, Long> last = readLastInstants();
        if (!settings.realTime() && !recorder.awaitAnswered(last, SETTLE)) {
          System.out.println("the robots' last instants were not all answered within " + SETTLE);
        }
        writeLoop(out.resolve(Reflection.META_LOOP), recorder.lines());
        writeFigures(out.resolve(Reflection.META_FIGURES), level.figures());
        System.out.println("meta level of " + example + " leaves");
      } finally {
        presence.close();
        kernel.close();
        runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
      }
    }
  }

  /**
   * The example named {@code name}, among the {@link SimExample} services on the class path: the
   * shipped robots (listed in examples' {@code META-INF/services}) and any a jar adds (a
   * benchmark's robot, say).
   */
  static Optional<SimExample> find(String name) {
    return java.util.ServiceLoader.load(SimExample.class).stream()
        .map(java.util.ServiceLoader.Provider::get)
        .filter(e -> e.name().equals(name))
        .findFirst();
  }

  /** Reads {@code <robot> <instant>} lines until the end of standard input. */
  private static Map<String, Long> readLastInstants() throws IOException {
    Map<String, Long> last = new LinkedHashMap<>();
    BufferedReader in =
        new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
    String line;
    while ((line = in.readLine()) != null) {
      String[] parts = line.trim().split(" ");
      if (parts.length == 2) {
        last.put(parts[0], Long.parseLong(parts[1]));
      }
    }
    return last;
  }

  static void writeLoop(Path file, List<LoopRecorder.Line> lines) {
    try (Writer w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
      for (LoopRecorder.Line l : lines) {
        Map<String, Object> record = new LinkedHashMap<>();
        record.put("cycle", l.cycle());
        record.putAll(l.fields());
        w.write(LoopJson.write(record));
        w.write('\n');
      }
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write " + file, e);
    }
  }

  private static void writeFigures(Path file, List<Summary.Entry> figures) {
    try (Writer w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
      for (Summary.Entry e : figures) {
        w.write(LoopJson.write(Map.of("name", e.name(), "value", e.value())));
        w.write('\n');
      }
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write " + file, e);
    }
  }

  /** The meta side of the loop's record a meta level's JVM wrote; empty if it wrote none. */
  static List<LoopRecorder.Line> readLoop(Path file) {
    List<LoopRecorder.Line> lines = new ArrayList<>();
    for (Map<?, ?> record : readJsonLines(file)) {
      lines.add(LoopRecorder.read(record, lines.size()));
    }
    return lines;
  }

  /** The figures a meta level's JVM wrote; empty if it wrote none. */
  static List<Summary.Entry> readFigures(Path file) {
    List<Summary.Entry> figures = new ArrayList<>();
    for (Map<?, ?> record : readJsonLines(file)) {
      figures.add(
          new Summary.Entry(
              String.valueOf(record.get("name")), String.valueOf(record.get("value"))));
    }
    return figures;
  }

  private static List<Map<?, ?>> readJsonLines(Path file) {
    requireNonNull(file, "file");
    if (!Files.exists(file)) {
      return List.of();
    }
    List<Map<?, ?>> records = new ArrayList<>();
    try {
      for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
        if (!line.isBlank() && TraceJson.parse(line) instanceof Map<?, ?> m) {
          records.add(m);
        }
      }
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read " + file, e);
    }
    return records;
  }
}
