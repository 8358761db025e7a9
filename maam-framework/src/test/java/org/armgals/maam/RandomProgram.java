package org.armgals.maam;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

/**
 * A random program whose graph is a DAG by construction: modules get a hidden global rank, and
 * every wire and connector goes from a lower rank to a higher one. Built again from the same seed,
 * it is the same program.
 */
final class RandomProgram {

  /** Input ports {@code 0..FREE_INPUTS-1} take wires and connectors; the last is kept free. */
  static final int FREE_INPUTS = 6;

  final List<Schema> schemas = new ArrayList<>();
  final List<Connector> connectors = new ArrayList<>();
  final Map<String, Node> modules = new HashMap<>();

  /** Every edge of the graph, as {source, target} module names. */
  final List<String[]> edges = new ArrayList<>();

  RandomProgram(long seed, int maxSchemas, int maxModulesPerSchema) {
    Random random = new Random(seed);
    int schemaCount = 1 + random.nextInt(maxSchemas);
    List<List<Node>> bySchema = new ArrayList<>();
    List<Node> all = new ArrayList<>();
    List<String> trace = new ArrayList<>();
    for (int s = 0; s < schemaCount; s++) {
      List<Node> nodes = new ArrayList<>();
      int size = 1 + random.nextInt(maxModulesPerSchema);
      for (int m = 0; m < size; m++) {
        Node node = new Node("s" + s + "m" + m, FREE_INPUTS + 1, 1 + m % 3, trace);
        nodes.add(node);
        all.add(node);
        modules.put(node.name(), node);
      }
      bySchema.add(nodes);
    }
    List<Node> ranked = new ArrayList<>(all);
    Collections.shuffle(ranked, random);
    Map<String, Integer> rank = new HashMap<>();
    for (int i = 0; i < ranked.size(); i++) {
      rank.put(ranked.get(i).name(), i);
    }
    Map<String, Integer> nextInput = new HashMap<>();
    for (int s = 0; s < schemaCount; s++) {
      List<Node> nodes = bySchema.get(s);
      Schema.Builder builder = Schema.builder("schema" + s);
      int start = 0;
      while (start < nodes.size()) {
        int end = Math.min(nodes.size(), start + 1 + random.nextInt(3));
        builder.add(
            new ReactiveModule("r" + s + "_" + start, List.copyOf(nodes.subList(start, end))));
        start = end;
      }
      int wires = random.nextInt(nodes.size() * 2 + 1);
      for (int w = 0; w < wires; w++) {
        Node a = nodes.get(random.nextInt(nodes.size()));
        Node b = nodes.get(random.nextInt(nodes.size()));
        if (rank.get(a.name()) >= rank.get(b.name())) {
          continue;
        }
        int input = nextInput.merge(b.name(), 1, Integer::sum) - 1;
        if (input >= FREE_INPUTS) {
          continue;
        }
        builder.wire(a, Node.OUT, b, Node.in(input));
        edges.add(new String[] {a.name(), b.name()});
      }
      schemas.add(builder.build());
    }
    int connectorCount = random.nextInt(all.size() * 2 + 1);
    for (int c = 0; c < connectorCount; c++) {
      Node a = all.get(random.nextInt(all.size()));
      Node b = all.get(random.nextInt(all.size()));
      if (rank.get(a.name()) >= rank.get(b.name())) {
        continue;
      }
      PortRef source = PortRef.of(a, Node.OUT);
      Duration hold = Duration.ofMillis(random.nextInt(3));
      int kind = random.nextInt(3);
      if (kind == 0) {
        connectors.add(new Suppressor(source, PortRef.of(b, Node.OUT), hold));
      } else {
        int input = nextInput.merge(b.name(), 1, Integer::sum) - 1;
        if (input >= FREE_INPUTS) {
          continue;
        }
        PortRef target = PortRef.of(b, Node.in(input));
        connectors.add(
            kind == 1 ? new Inhibitor(source, target, hold) : new Derivator(source, target));
      }
      edges.add(new String[] {a.name(), b.name()});
    }
  }

  /**
   * The order the Scheduler's rules give, computed the slow, obvious way: each schema's modules
   * ordered by repeatedly taking the first ready one in declaration order; then all modules by
   * repeatedly taking the first ready one in (schema, partial order).
   */
  List<String> expectedOrder() {
    List<String> priority = new ArrayList<>();
    for (Schema schema : schemas) {
      List<String> declared = schema.modules().stream().map(BehaviorModule::name).toList();
      List<String[]> internal = new ArrayList<>();
      for (Wire wire : schema.wires()) {
        internal.add(new String[] {wire.from().module(), wire.to().module()});
      }
      priority.addAll(firstReadyOrder(declared, internal));
    }
    return firstReadyOrder(priority, edges);
  }

  static List<String> firstReadyOrder(List<String> priority, List<String[]> edges) {
    Map<String, Integer> indegree = new HashMap<>();
    Map<String, List<String>> successors = new HashMap<>();
    for (String name : priority) {
      indegree.put(name, 0);
    }
    for (String[] edge : edges) {
      if (indegree.containsKey(edge[0]) && indegree.containsKey(edge[1])) {
        indegree.merge(edge[1], 1, Integer::sum);
        successors.computeIfAbsent(edge[0], k -> new ArrayList<>()).add(edge[1]);
      }
    }
    List<String> left = new ArrayList<>(priority);
    List<String> order = new ArrayList<>();
    while (!left.isEmpty()) {
      String ready = null;
      for (String candidate : left) {
        if (indegree.get(candidate) == 0) {
          ready = candidate;
          break;
        }
      }
      if (ready == null) {
        throw new AssertionError("the reference found a cycle among " + left);
      }
      order.add(ready);
      left.remove(ready);
      for (String next : successors.getOrDefault(ready, List.of())) {
        indegree.merge(next, -1, Integer::sum);
      }
    }
    return order;
  }
}
