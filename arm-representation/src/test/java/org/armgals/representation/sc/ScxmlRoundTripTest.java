package org.armgals.representation.sc;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** {@code read(write(d))} equals {@code d} for every definition {@code d} that was read. */
class ScxmlRoundTripTest {

  /** Every SCXML document of this package's test resources, subdirectories included. */
  static Stream<Path> charts() throws IOException, URISyntaxException {
    URL here = ScxmlRoundTripTest.class.getResource("robot.scxml");
    Path dir = Path.of(here.toURI()).getParent();
    List<Path> found = new ArrayList<>();
    try (Stream<Path> all = Files.walk(dir)) {
      all.filter(p -> p.toString().endsWith(".scxml")).sorted().forEach(found::add);
    }
    assertThat(found).hasSizeGreaterThan(15);
    return found.stream();
  }

  @ParameterizedTest
  @MethodSource("charts")
  void readingWhatWasWrittenGivesTheDefinitionRead(Path chart) throws IOException {
    ScDefinition d = Scxml.read(Files.readString(chart, StandardCharsets.UTF_8));
    String written = Scxml.write(d);
    assertThat(Scxml.read(written)).isEqualTo(d);
    assertThat(Scxml.write(Scxml.read(written))).isEqualTo(written);
  }

  // A transition of a parent listed after its children's transitions, and before those of a
  // later child: the writer keeps that place.
  @Test
  void aParentsTransitionKeepsItsPlaceAmongItsChildrensTransitions() {
    ScDefinition d =
        Scxml.read(
            """
            <scxml xmlns="http://www.w3.org/2005/07/scxml" version="1.0">
              <state id="P">
                <state id="A"><transition event="a" target="B"/></state>
                <transition event="p" target="Q"/>
                <state id="B"><transition event="b" target="A"/></state>
                <transition event="q" target="Q"/>
              </state>
              <state id="Q"/>
            </scxml>
            """);
    assertThat(d.transitions())
        .extracting(ScTransition::id)
        .containsExactly("A#1", "P#1", "B#1", "P#2");
    assertThat(Scxml.read(Scxml.write(d))).isEqualTo(d);
  }

  // The same property over generated charts: states nested at random, transitions leaving
  // random states, listed in an order a document can have (each state's transitions at random
  // places among its children, as a reader lists them).
  @Test
  void readingWhatWasWrittenGivesTheDefinitionForGeneratedCharts() {
    for (long seed = 0; seed < 300; seed++) {
      Random random = new Random(seed);
      List<String> sources = new ArrayList<>();
      List<ScNode> top = new ArrayList<>();
      int[] next = {0};
      int count = 1 + random.nextInt(4);
      for (int i = 0; i < count; i++) {
        top.add(node(random, 0, false, next, sources));
      }
      Map<String, List<Map.Entry<Integer, ScTransition>>> placed = new HashMap<>();
      int n = random.nextInt(12);
      for (int i = 0; i < n && !sources.isEmpty(); i++) {
        String source = sources.get(random.nextInt(sources.size()));
        String target = sources.get(random.nextInt(sources.size()));
        ScTransition t = ScTransition.on("t" + i, source, "e" + random.nextInt(3), target);
        t = random.nextBoolean() ? t : t.doing(actions(random));
        t = random.nextBoolean() ? t : t.when("In('" + target + "') || _event.name < 'e1'");
        t = random.nextInt(4) > 0 ? t : t.asInternal();
        placed.computeIfAbsent(source, k -> new ArrayList<>()).add(Map.entry(random.nextInt(4), t));
      }
      List<ScTransition> transitions = new ArrayList<>();
      for (ScNode node : top) {
        inDocumentOrder(node, placed, transitions);
      }
      List<String> initial =
          random.nextBoolean() ? List.of() : List.of(top.get(random.nextInt(top.size())).id());
      ScDefinition generated = new ScDefinition("g" + seed, initial, top, transitions);
      assertThat(Scxml.read(Scxml.write(generated))).as("seed %d", seed).isEqualTo(generated);
    }
  }

  /** The transitions as a document lists them: those placed at slot k after the k-th child. */
  private static void inDocumentOrder(
      ScNode node,
      Map<String, List<Map.Entry<Integer, ScTransition>>> placed,
      List<ScTransition> out) {
    List<Map.Entry<Integer, ScTransition>> own = placed.getOrDefault(node.id(), List.of());
    for (int k = 0; k <= node.children().size(); k++) {
      int slot = Math.min(k, node.children().size());
      for (Map.Entry<Integer, ScTransition> e : own) {
        if (Math.min(e.getKey(), node.children().size()) == slot) {
          out.add(e.getValue());
        }
      }
      if (k < node.children().size()) {
        inDocumentOrder(node.children().get(k), placed, out);
      }
    }
  }

  private static ScNode node(
      Random random, int depth, boolean inParallel, int[] next, List<String> sources) {
    String id = "s" + next[0]++;
    int kind = depth > 2 ? 0 : random.nextInt(4);
    if (kind == 3 && !inParallel) {
      ScNode end = ScNode.finalState(id).onEntry(actions(random));
      ScData[] done = data();
      return random.nextBoolean() ? end : end.withDoneData(done[random.nextInt(done.length)]);
    }
    sources.add(id);
    if (kind == 0 || kind == 3) {
      return ScNode.state(id).onEntry(ScAction.run("in" + id)).onExit(actions(random));
    }
    List<ScNode> children = new ArrayList<>();
    for (int i = 1 + random.nextInt(3); i > 0; i--) {
      children.add(node(random, depth + 1, kind == 2, next, sources));
    }
    if (random.nextInt(3) == 0) {
      String target = children.get(random.nextInt(children.size())).id();
      ScNode history = ScNode.history(id + "h", random.nextBoolean(), target);
      children.add(
          random.nextInt(children.size() + 1),
          random.nextBoolean() ? history : history.onDefault(actions(random)));
    }
    ScNode node =
        kind == 1
            ? ScNode.state(id, children.toArray(ScNode[]::new))
            : ScNode.parallel(id, children.toArray(ScNode[]::new));
    node = node.onEntry(actions(random));
    if (kind == 1 && random.nextBoolean()) {
      String first = children.get(random.nextInt(children.size())).id();
      node = node.withInitial(first);
      if (random.nextBoolean()) {
        node = node.onDefault(actions(random));
      }
    }
    return node;
  }

  /** Event data of every kind, text with markup, white space and line breaks included. */
  private static ScData[] data() {
    return new ScData[] {
      ScData.params(
          ScData.param("a b", "1"),
          ScData.param("k", "_event.data.k"),
          ScData.param("k", "In('s0')")),
      ScData.text("  {\"a\": [1, 2]}\r\n\t<x> & ]]> y  "),
      ScData.text(""),
      ScData.expr("'v' == _event.name")
    };
  }

  /** Zero to two actions of any kind, text with markup, tabs and line breaks included. */
  private static ScAction[] actions(Random random) {
    ScData[] data = data();
    ScAction[] all = {
      ScAction.run("a&b"),
      ScAction.raise("r.x"),
      ScAction.log("<\"label\">", "_event.data.n >= 2 &&\n\t'x' != \"y\""),
      ScAction.log(null, null),
      ScAction.log("only", null),
      ScAction.send("e.x"),
      ScAction.send("go").toInternalQueue().with(data[random.nextInt(data.length)]),
      ScAction.sendExpr("_event.data.next").with(data[random.nextInt(data.length)]),
      ScAction.when("In('s1') && true", ScAction.run("y"))
          .orElseIf("false")
          .orElseIf("_event.data.x < 3", ScAction.raise("z"), ScAction.send("w")),
      ScAction.when(
              "true", ScAction.when("!false", ScAction.send("deep")).orElse(ScAction.run("no")))
          .orElse()
    };
    ScAction[] chosen = new ScAction[random.nextInt(3)];
    for (int i = 0; i < chosen.length; i++) {
      chosen[i] = all[random.nextInt(all.length)];
    }
    return chosen;
  }
}
