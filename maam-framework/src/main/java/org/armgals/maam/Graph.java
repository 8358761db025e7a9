package org.armgals.maam;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.function.IntFunction;

/**
 * A directed graph over nodes {@code 0..n-1}, sorted topologically with ties broken by the smallest
 * node number first (Kahn's algorithm over a binary heap of ints: O((n + e) log n), no boxing).
 * Numbers are priorities: callers number nodes in the order they want ties broken.
 */
final class Graph {

  private final int nodes;
  private int[] from = new int[16];
  private int[] to = new int[16];
  private int edges;

  Graph(int nodes) {
    this.nodes = nodes;
  }

  void edge(int source, int target) {
    if (edges == from.length) {
      from = Arrays.copyOf(from, edges * 2);
      to = Arrays.copyOf(to, edges * 2);
    }
    from[edges] = source;
    to[edges] = target;
    edges++;
  }

  /**
   * The nodes in topological order, smallest number first among those ready.
   *
   * @throws CycleException naming the nodes of one cycle with {@code names}
   */
  int[] order(String where, IntFunction<String> names) {
    int[] offsets = new int[nodes + 1];
    int[] indegree = new int[nodes];
    for (int e = 0; e < edges; e++) {
      offsets[from[e] + 1]++;
      indegree[to[e]]++;
    }
    for (int v = 0; v < nodes; v++) {
      offsets[v + 1] += offsets[v];
    }
    int[] targets = new int[edges];
    int[] fill = Arrays.copyOf(offsets, nodes);
    for (int e = 0; e < edges; e++) {
      targets[fill[from[e]]++] = to[e];
    }
    int[] heap = new int[nodes];
    int size = 0;
    for (int v = 0; v < nodes; v++) {
      if (indegree[v] == 0) {
        heap[size++] = v; // ascending, so already a heap
      }
    }
    int[] order = new int[nodes];
    int done = 0;
    while (size > 0) {
      int v = heap[0];
      heap[0] = heap[--size];
      siftDown(heap, size);
      order[done++] = v;
      for (int i = offsets[v]; i < offsets[v + 1]; i++) {
        int w = targets[i];
        if (--indegree[w] == 0) {
          siftUp(heap, size++, w);
        }
      }
    }
    if (done < nodes) {
      throw new CycleException(where, cycle(indegree, names));
    }
    return order;
  }

  /**
   * One cycle among the nodes left with incoming edges: each has a predecessor also left, so
   * walking predecessors from the smallest one must come back to a node already seen.
   */
  private List<String> cycle(int[] indegree, IntFunction<String> names) {
    int start = 0;
    while (indegree[start] == 0) {
      start++;
    }
    int[] predecessor = new int[nodes];
    Arrays.fill(predecessor, -1);
    for (int e = 0; e < edges; e++) {
      int p = from[e];
      int v = to[e];
      if (indegree[p] > 0 && indegree[v] > 0 && (predecessor[v] < 0 || p < predecessor[v])) {
        predecessor[v] = p;
      }
    }
    int[] seenAt = new int[nodes];
    Arrays.fill(seenAt, -1);
    List<Integer> walk = new ArrayList<>();
    int v = start;
    while (seenAt[v] < 0) {
      seenAt[v] = walk.size();
      walk.add(v);
      v = predecessor[v];
    }
    List<Integer> loop = new ArrayList<>(walk.subList(seenAt[v], walk.size()));
    Collections.reverse(loop); // predecessors walked backwards: now each feeds the next
    int smallest = 0;
    for (int i = 1; i < loop.size(); i++) {
      if (loop.get(i) < loop.get(smallest)) {
        smallest = i;
      }
    }
    Collections.rotate(loop, -smallest);
    List<String> cycle = new ArrayList<>(loop.size());
    for (int node : loop) {
      cycle.add(names.apply(node));
    }
    return cycle;
  }

  private static void siftUp(int[] heap, int at, int value) {
    int i = at;
    while (i > 0) {
      int parent = (i - 1) >>> 1;
      if (heap[parent] <= value) {
        break;
      }
      heap[i] = heap[parent];
      i = parent;
    }
    heap[i] = value;
  }

  private static void siftDown(int[] heap, int size) {
    if (size == 0) {
      return;
    }
    int value = heap[0];
    int i = 0;
    int half = size >>> 1;
    while (i < half) {
      int child = 2 * i + 1;
      if (child + 1 < size && heap[child + 1] < heap[child]) {
        child++;
      }
      if (value <= heap[child]) {
        break;
      }
      heap[i] = heap[child];
      i = child;
    }
    heap[i] = value;
  }
}
