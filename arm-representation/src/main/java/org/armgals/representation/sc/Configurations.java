package org.armgals.representation.sc;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.armgals.representation.sc.Chart.Node;
import org.jspecify.annotations.Nullable;

/** The legal configurations of a chart: the check of one, and the enumeration of all. */
final class Configurations {
  /** mapToState enumerates legal configurations; beyond this many it refuses. */
  static final int MAX_CONFIGURATIONS = 100_000;

  private final Chart chart;
  private final String name;
  private volatile @Nullable List<Set<String>> all;

  Configurations(Chart chart, String name) {
    this.chart = chart;
    this.name = name;
  }

  /** Whether the active states under {@code node} form one legal configuration of it. */
  static boolean legal(Node node, Set<Node> active) {
    int on = 0;
    for (Node child : node.stateChildren()) {
      if (active.contains(child)) {
        on++;
        if (!legal(child, active)) {
          return false;
        }
      } else if (hasActiveDescendant(child, active)) {
        return false;
      }
    }
    if (node.isParallel()) {
      return on == node.stateChildren().size();
    }
    return node.stateChildren().isEmpty() ? on == 0 : on == 1;
  }

  private static boolean hasActiveDescendant(Node node, Set<Node> active) {
    for (Node a : active) {
      if (a.isDescendantOf(node)) {
        return true;
      }
    }
    return false;
  }

  /** Every legal set of active states, each in document order; computed once, when first asked. */
  List<Set<String>> all() {
    List<Set<String>> result = all;
    if (result == null) {
      List<List<Node>> found = new ArrayList<>();
      for (Node top : chart.root.stateChildren()) {
        found.addAll(enumerate(top));
      }
      List<Set<String>> ids = new ArrayList<>();
      for (List<Node> config : found) {
        config.sort(Chart.DOCUMENT_ORDER);
        ids.add(Collections.unmodifiableSet(new LinkedHashSet<>(Chart.ids(config))));
      }
      result = List.copyOf(ids);
      this.all = result;
    }
    return result;
  }

  private List<List<Node>> enumerate(Node node) {
    List<List<Node>> result = new ArrayList<>();
    if (node.isAtomic()) {
      result.add(new ArrayList<>(List.of(node)));
    } else if (node.isParallel()) {
      result.add(new ArrayList<>(List.of(node)));
      for (Node region : node.stateChildren()) {
        List<List<Node>> next = new ArrayList<>();
        for (List<Node> prefix : result) {
          for (List<Node> sub : enumerate(region)) {
            List<Node> config = new ArrayList<>(prefix);
            config.addAll(sub);
            next.add(config);
            tooMany(next.size());
          }
        }
        result = next;
      }
    } else {
      for (Node child : node.stateChildren()) {
        for (List<Node> sub : enumerate(child)) {
          List<Node> config = new ArrayList<>(List.of(node));
          config.addAll(sub);
          result.add(config);
          tooMany(result.size());
        }
      }
    }
    return result;
  }

  private void tooMany(int count) {
    if (count > MAX_CONFIGURATIONS) {
      throw new IllegalStateException(
          "chart '"
              + name
              + "' has more than "
              + MAX_CONFIGURATIONS
              + " configurations; mapToState cannot enumerate them");
    }
  }
}
