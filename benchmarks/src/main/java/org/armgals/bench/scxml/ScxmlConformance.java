package org.armgals.bench.scxml;

import java.io.IOException;
import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.armgals.representation.Activation;
import org.armgals.representation.sc.Configuration;
import org.armgals.representation.sc.ScAction;
import org.armgals.representation.sc.ScDefinition;
import org.armgals.representation.sc.ScNode;
import org.armgals.representation.sc.ScTransition;
import org.armgals.representation.sc.Scxml;
import org.armgals.representation.sc.Statechart;
import org.jspecify.annotations.Nullable;

/**
 * Runs every {@code .scxml} chart under a directory of the SCION test framework ({@code npm
 * pack @scion-scxml/test-framework@2.0.16}, its {@code test/} directory) through {@link
 * Scxml#read}, {@link Statechart#of} and the events of the chart's {@code .json} script, comparing
 * the atomic states of each configuration with the script's. Prints one line per chart and a
 * summary:
 *
 * <ul>
 *   <li>{@code pass}: every configuration is the script's;
 *   <li>{@code pass-queued}: the same, except the initial configuration, where SCION's is taken
 *       before the events the chart sent itself at start and ours after them (a dispatch takes the
 *       external events the chart sent itself, {@code docs/representations.md}); the chart's
 *       initial configuration without its external sends is the script's;
 *   <li>{@code fail}: a configuration differs, or the run threw;
 *   <li>{@code refused}: the reader or {@link Statechart#of} refused the chart (outside the
 *       subset); the summary counts refusals by what they name;
 *   <li>{@code no-script}: no {@code .json} (a chart another one invokes);
 *   <li>{@code roundtrip-fail}, counted apart: {@code Scxml.read(Scxml.write(d))} is not {@code d}.
 * </ul>
 *
 * <p>Exits with 1 if a chart fails or does not round-trip.
 */
public final class ScxmlConformance {

  private ScxmlConformance() {}

  /** What a refusal names, first match wins, in the order of the summary. */
  private static final Map<String, Pattern> REFUSALS = new LinkedHashMap<>();

  static {
    REFUSALS.put(
        "a data model or an assignment",
        Pattern.compile(
            "element <datamodel>|element <data>|element <assign>|binding|location of <param>"
                + "|namelist|idlocation|XML in <content>|variable of a data model"
                + "|system variable of the data model|_event other than"
                + "|data model.s event variable"));
    REFUSALS.put("<invoke>", Pattern.compile("element <invoke>|<finalize>"));
    REFUSALS.put("<send> with a delay", Pattern.compile("<send> with a delay"));
    REFUSALS.put(
        "<send> to another target or I/O processor",
        Pattern.compile(
            "target '[^']*' of <send>|targetexpr of <send>|type '[^']*' of <send>"
                + "|typeexpr of <send>"));
    REFUSALS.put("<script>", Pattern.compile("element <script>"));
    REFUSALS.put(
        "an ECMAScript expression outside the condition language", Pattern.compile("ECMAScript's"));
  }

  public static void main(String[] args) throws IOException {
    if (args.length != 1) {
      System.err.println("usage: ScxmlConformance <the SCION test framework's test directory>");
      System.exit(2);
    }
    Path root = Path.of(args[0]);
    if (!Files.isDirectory(root)) {
      System.err.println("ScxmlConformance: '" + root + "' is not a directory");
      System.exit(2);
    }
    List<Path> files;
    try (Stream<Path> walk = Files.walk(root)) {
      files = walk.filter(p -> p.toString().endsWith(".scxml")).sorted().toList();
    }
    Map<String, Integer> counts = new LinkedHashMap<>();
    for (String result : List.of("pass", "pass-queued", "fail", "refused", "no-script")) {
      counts.put(result, 0);
    }
    Map<String, Integer> refusals = new LinkedHashMap<>();
    int roundTripFailures = 0;
    for (Path file : files) {
      String name = root.relativize(file).toString();
      String result;
      String detail = "";
      ScDefinition d = null;
      Statechart chart = null;
      try {
        d = Scxml.read(Files.readString(file));
        chart = Statechart.of(d);
      } catch (RuntimeException e) {
        detail = String.valueOf(e.getMessage());
        refusals.merge(category(detail), 1, Integer::sum);
      }
      if (d != null && !Scxml.read(Scxml.write(d)).equals(d)) {
        roundTripFailures++;
        System.out.println("scxml chart=" + name + " roundtrip-fail");
      }
      if (d == null || chart == null) {
        result = "refused";
      } else {
        Path script = Path.of(file.toString().replaceAll("\\.scxml$", ".json"));
        if (!Files.exists(script)) {
          result = "no-script";
          detail = "initial " + atomic(d, chart.initialState());
        } else {
          String problem = run(d, chart, Json.parse(Files.readString(script)));
          result = problem == null ? "pass" : problem.startsWith("queued") ? "pass-queued" : "fail";
          detail = problem == null || result.equals("pass-queued") ? "" : problem;
        }
      }
      counts.merge(result, 1, Integer::sum);
      System.out.println(
          "scxml chart=" + name + " result=" + result + (detail.isEmpty() ? "" : " :: " + detail));
    }
    StringBuilder summary = new StringBuilder("scxml charts=" + files.size());
    counts.forEach((k, v) -> summary.append(' ').append(k).append('=').append(v));
    summary.append(" roundtrip-fail=").append(roundTripFailures);
    System.out.println(summary);
    refusals.entrySet().stream()
        .sorted(Map.Entry.<String, Integer>comparingByValue().reversed())
        .forEach(e -> System.out.println("scxml refused=" + e.getValue() + " :: " + e.getKey()));
    if (counts.get("fail") > 0 || roundTripFailures > 0) {
      System.exit(1);
    }
  }

  private static String category(String message) {
    for (Map.Entry<String, Pattern> e : REFUSALS.entrySet()) {
      if (e.getValue().matcher(message).find()) {
        return e.getKey();
      }
    }
    return "other: " + message;
  }

  /**
   * Runs the script; null if every configuration is the script's, "queued" if only the initial
   * differs as SCION's start does, else what differed.
   */
  private static @Nullable String run(ScDefinition d, Statechart chart, @Nullable Object script) {
    if (!(script instanceof Map<?, ?> steps)) {
      return "the script is not a JSON object";
    }
    boolean queued = false;
    try {
      Activation<Configuration> a = chart.activate(chart.initialState(), chart.transitions());
      Set<String> expected = strings(steps.get("initialConfiguration"));
      if (!atomic(d, a.state()).equals(expected)) {
        ScDefinition bare = withoutExternalSends(d);
        if (!bare.equals(d) && atomic(bare, Statechart.of(bare).initialState()).equals(expected)) {
          queued = true;
        } else {
          return "initial " + atomic(d, a.state()) + " expected " + expected;
        }
      }
      Object events = steps.get("events");
      int i = 0;
      for (Object step : events instanceof List<?> l ? l : List.of()) {
        Map<?, ?> s = (Map<?, ?>) step;
        Map<?, ?> event = (Map<?, ?>) s.get("event");
        a.dispatch(String.valueOf(event.get("name")), event.get("data"));
        expected = strings(s.get("nextConfiguration"));
        if (!atomic(d, a.state()).equals(expected)) {
          return "after event #"
              + i
              + " '"
              + event.get("name")
              + "': "
              + atomic(d, a.state())
              + " expected "
              + expected;
        }
        i++;
      }
    } catch (RuntimeException e) {
      return "threw " + e;
    }
    return queued ? "queued" : null;
  }

  private static Set<String> strings(@Nullable Object list) {
    Set<String> out = new TreeSet<>();
    if (list instanceof List<?> l) {
      l.forEach(o -> out.add(String.valueOf(o)));
    }
    return out;
  }

  /** The active atomic states of {@code c}: the states SCION's scripts list. */
  private static Set<String> atomic(ScDefinition d, Configuration c) {
    Set<String> atomic = new TreeSet<>();
    d.states().forEach(n -> atomic(n, atomic));
    Set<String> out = new TreeSet<>(c.active());
    out.retainAll(atomic);
    return out;
  }

  private static void atomic(ScNode n, Set<String> out) {
    if (n.kind().isHistory()) {
      return;
    }
    if (n.children().stream().allMatch(c -> c.kind().isHistory())) {
      out.add(n.id());
    }
    n.children().forEach(c -> atomic(c, out));
  }

  private static ScDefinition withoutExternalSends(ScDefinition d) {
    List<ScNode> states = d.states().stream().map(ScxmlConformance::strip).toList();
    List<ScTransition> transitions =
        d.transitions().stream()
            .map(
                t ->
                    new ScTransition(
                        t.id(),
                        t.source(),
                        t.events(),
                        t.cond(),
                        t.targets(),
                        t.internal(),
                        strip(t.actions())))
            .toList();
    return new ScDefinition(d.name(), d.initial(), states, transitions);
  }

  private static ScNode strip(ScNode n) {
    return new ScNode(
        n.id(),
        n.kind(),
        n.initial(),
        strip(n.onEntry()),
        strip(n.onExit()),
        n.historyDefault(),
        n.children().stream().map(ScxmlConformance::strip).toList(),
        strip(n.defaultActions()),
        n.doneData());
  }

  private static List<ScAction> strip(List<ScAction> actions) {
    List<ScAction> out = new ArrayList<>();
    for (ScAction action : actions) {
      switch (action) {
        case ScAction.Send s when !s.internal() -> {}
        case ScAction.If i ->
            out.add(
                new ScAction.If(
                    i.branches().stream()
                        .map(b -> new ScAction.Branch(b.cond(), strip(b.actions())))
                        .toList(),
                    strip(i.otherwise())));
        default -> out.add(action);
      }
    }
    return out;
  }

  /** The JSON of SCION's scripts: objects, arrays, strings, numbers, booleans and null. */
  private static final class Json {
    private static final Pattern NUMBER =
        Pattern.compile("-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][+-]?[0-9]+)?");
    private final String text;
    private int at;

    private Json(String text) {
      this.text = text;
    }

    static @Nullable Object parse(String text) {
      Json json = new Json(text);
      Object value = json.value();
      json.space();
      if (json.at != text.length()) {
        throw json.error("the end");
      }
      return value;
    }

    private @Nullable Object value() {
      space();
      if (at >= text.length()) {
        throw error("a value");
      }
      char c = text.charAt(at);
      switch (c) {
        case '{' -> {
          at++;
          Map<String, @Nullable Object> map = new TreeMap<>();
          space();
          if (take('}')) {
            return map;
          }
          do {
            space();
            if (!(value() instanceof String key)) {
              throw error("a key");
            }
            space();
            expect(':');
            map.put(key, value());
            space();
          } while (take(','));
          expect('}');
          return map;
        }
        case '[' -> {
          at++;
          List<@Nullable Object> list = new ArrayList<>();
          space();
          if (take(']')) {
            return list;
          }
          do {
            list.add(value());
            space();
          } while (take(','));
          expect(']');
          return list;
        }
        case '"' -> {
          return string();
        }
        default -> {
          for (String word : List.of("true", "false", "null")) {
            if (text.startsWith(word, at)) {
              at += word.length();
              return word.equals("null") ? null : Boolean.valueOf(word);
            }
          }
          Matcher m = NUMBER.matcher(text).region(at, text.length());
          if (!m.lookingAt()) {
            throw error("a value");
          }
          at = m.end();
          return new BigDecimal(m.group());
        }
      }
    }

    private String string() {
      StringBuilder out = new StringBuilder();
      at++;
      while (at < text.length() && text.charAt(at) != '"') {
        char c = text.charAt(at++);
        if (c != '\\') {
          out.append(c);
          continue;
        }
        char e = text.charAt(at++);
        switch (e) {
          case 'n' -> out.append('\n');
          case 't' -> out.append('\t');
          case 'r' -> out.append('\r');
          case 'b' -> out.append('\b');
          case 'f' -> out.append('\f');
          case 'u' -> {
            out.append((char) Integer.parseInt(text.substring(at, at + 4), 16));
            at += 4;
          }
          default -> out.append(e);
        }
      }
      expect('"');
      return out.toString();
    }

    private void space() {
      while (at < text.length() && Character.isWhitespace(text.charAt(at))) {
        at++;
      }
    }

    private boolean take(char c) {
      if (at < text.length() && text.charAt(at) == c) {
        at++;
        return true;
      }
      return false;
    }

    private void expect(char c) {
      if (!take(c)) {
        throw error("'" + c + "'");
      }
    }

    private IllegalArgumentException error(String expected) {
      return new IllegalArgumentException("JSON at " + at + ": expected " + expected);
    }
  }
}
