package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The Scheduler's rules, on thousands of random programs (seeded: a failure names its seed). */
class SchedulerPropertiesTest {

  private static final int PROGRAMS = 2_000;
  private final Scheduler scheduler = Scheduler.topological();

  @Test
  void everyWireAndConnectorRunsSourceBeforeTarget() {
    for (long seed = 0; seed < PROGRAMS; seed++) {
      RandomProgram program = new RandomProgram(seed, 6, 12);
      List<String> order = scheduler.schedule(program.schemas, program.connectors).names();
      Map<String, Integer> position = new HashMap<>();
      for (int i = 0; i < order.size(); i++) {
        position.put(order.get(i), i);
      }
      assertThat(position).as("seed %d: every module once", seed).hasSize(program.modules.size());
      for (String[] edge : program.edges) {
        if (position.get(edge[0]) >= position.get(edge[1])) {
          throw new AssertionError("seed " + seed + ": " + edge[1] + " runs before " + edge[0]);
        }
      }
    }
  }

  @Test
  void tiesAreBrokenBySchemaThenPartialScheduleOrder() {
    for (long seed = 0; seed < PROGRAMS; seed++) {
      RandomProgram program = new RandomProgram(seed, 6, 12);
      assertThat(scheduler.schedule(program.schemas, program.connectors).names())
          .as("seed %d", seed)
          .isEqualTo(program.expectedOrder());
    }
  }

  @Test
  void theSameProgramGivesTheSameOrderEveryTime() {
    for (long seed = 0; seed < PROGRAMS; seed += 3) {
      RandomProgram program = new RandomProgram(seed, 6, 12);
      List<String> first = scheduler.schedule(program.schemas, program.connectors).names();
      assertThat(scheduler.schedule(program.schemas, program.connectors).names())
          .as("seed %d, same objects", seed)
          .isEqualTo(first);
      RandomProgram again = new RandomProgram(seed, 6, 12);
      assertThat(scheduler.schedule(again.schemas, again.connectors).names())
          .as("seed %d, rebuilt", seed)
          .isEqualTo(first);
    }
  }

  @Test
  void everyPartialScheduleRespectsItsSchemasWires() {
    for (long seed = 0; seed < PROGRAMS; seed += 2) {
      for (Schema schema : new RandomProgram(seed, 4, 20).schemas) {
        List<String> partial = schema.partialSchedule().stream().map(BehaviorModule::name).toList();
        assertThat(partial)
            .containsExactlyInAnyOrderElementsOf(
                schema.modules().stream().map(BehaviorModule::name).toList());
        for (Wire wire : schema.wires()) {
          if (partial.indexOf(wire.from().module()) >= partial.indexOf(wire.to().module())) {
            throw new AssertionError("seed " + seed + ": " + wire + " not respected: " + partial);
          }
        }
      }
    }
  }

  @Test
  void aConnectorClosingACycleIsRefusedNamingTheModulesOnIt() {
    int cycles = 0;
    for (long seed = 0; seed < PROGRAMS; seed++) {
      RandomProgram program = new RandomProgram(seed, 6, 12);
      if (program.edges.isEmpty()) {
        continue;
      }
      Random random = new Random(seed);
      String[] edge = program.edges.get(random.nextInt(program.edges.size()));
      Node from = program.modules.get(edge[1]);
      Node to = program.modules.get(edge[0]);
      Inhibitor back =
          new Inhibitor(
              PortRef.of(from, Node.OUT),
              PortRef.of(to, Node.in(RandomProgram.FREE_INPUTS)),
              Duration.ZERO);
      List<Connector> connectors = new ArrayList<>(program.connectors);
      connectors.add(back);
      CycleException refused =
          catchThrowableOfType(
              CycleException.class, () -> scheduler.schedule(program.schemas, connectors));
      assertThat(refused).as("seed %d", seed).isNotNull();
      List<String[]> edges = new ArrayList<>(program.edges);
      edges.add(new String[] {edge[1], edge[0]});
      assertIsACycle(seed, refused.modules(), edges);
      assertThat(refused.getMessage()).contains(String.join(" -> ", refused.modules()));
      cycles++;
    }
    assertThat(cycles).isGreaterThan(PROGRAMS / 2);
  }

  @Test
  void aWireClosingACycleInsideASchemaIsRefusedWhenTheSchemaIsBuilt() {
    List<String> trace = new ArrayList<>();
    Node a = new Node("a", 1, 0, trace);
    Node b = new Node("b", 1, 0, trace);
    Node c = new Node("c", 1, 0, trace);
    Schema.Builder builder =
        Schema.builder("loop")
            .add(a)
            .add(b)
            .add(c)
            .wire(a, Node.OUT, b, Node.in(0))
            .wire(b, Node.OUT, c, Node.in(0))
            .wire(c, Node.OUT, a, Node.in(0));
    assertThatThrownBy(builder::build)
        .isInstanceOfSatisfying(
            CycleException.class, e -> assertThat(e.modules()).containsExactly("a", "b", "c"))
        .hasMessageContaining("schema 'loop'")
        .hasMessageContaining("a -> b -> c -> a");
  }

  @Test
  void aModuleNameUsedInTwoSchemasIsRefusedNamingBoth() {
    List<String> trace = new ArrayList<>();
    Schema one = Schema.builder("one").add(new Node("x", 0, 0, trace)).build();
    Schema two = Schema.builder("two").add(new Node("x", 0, 0, trace)).build();
    assertThatThrownBy(() -> scheduler.schedule(List.of(one, two), List.of()))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'x'")
        .hasMessageContaining("'one'")
        .hasMessageContaining("'two'");
  }

  @Test
  void aConnectorToAnUnknownModuleOrPortIsRefusedNamingIt() {
    List<String> trace = new ArrayList<>();
    Node a = new Node("a", 1, 0, trace);
    Schema schema = Schema.builder("s").add(a).build();
    Derivator toGhost = new Derivator(PortRef.of(a, Node.OUT), new PortRef("ghost", Node.in(0)));
    assertThatThrownBy(() -> scheduler.schedule(List.of(schema), List.of(toGhost)))
        .hasMessageContaining("'ghost'");
    Derivator toOutput = new Derivator(PortRef.of(a, Node.OUT), PortRef.of(a, Node.OUT));
    assertThatThrownBy(() -> scheduler.schedule(List.of(schema), List.of(toOutput)))
        .hasMessageContaining("a.out is not an input");
  }

  private static void assertIsACycle(long seed, List<String> cycle, List<String[]> edges) {
    Set<String> edgeSet = new HashSet<>();
    for (String[] edge : edges) {
      edgeSet.add(edge[0] + ">" + edge[1]);
    }
    assertThat(cycle).as("seed %d", seed).isNotEmpty().doesNotHaveDuplicates();
    for (int i = 0; i < cycle.size(); i++) {
      String from = cycle.get(i);
      String to = cycle.get((i + 1) % cycle.size());
      assertThat(edgeSet)
          .as("seed %d: cycle %s has edge %s -> %s", seed, cycle, from, to)
          .contains(from + ">" + to);
    }
  }
}
