package org.armgals.representation.sc;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** Writes a definition as SCXML; see {@link Scxml}. */
final class ScxmlWriter {
  private final StringBuilder out = new StringBuilder();
  private final Map<String, List<ScTransition>> bySource = new LinkedHashMap<>();
  // The place of each source's transitions in the definition's list, in the same order.
  private final Map<String, List<Integer>> places = new LinkedHashMap<>();

  private ScxmlWriter(ScDefinition definition) {
    List<ScTransition> all = definition.transitions();
    for (int i = 0; i < all.size(); i++) {
      ScTransition t = all.get(i);
      bySource.computeIfAbsent(t.source(), s -> new ArrayList<>()).add(t);
      places.computeIfAbsent(t.source(), s -> new ArrayList<>()).add(i);
    }
  }

  /** The first place of a transition leaving {@code node} or a descendant; -1 for none. */
  private int first(ScNode node) {
    int min = places.getOrDefault(node.id(), List.of(-1)).get(0);
    for (ScNode child : node.children()) {
      int c = first(child);
      if (c >= 0 && (min < 0 || c < min)) {
        min = c;
      }
    }
    return min;
  }

  static String write(ScDefinition definition) {
    ScxmlWriter w = new ScxmlWriter(definition);
    Set<String> ids = new LinkedHashSet<>();
    for (ScNode n : definition.states()) {
      collect(n, ids);
    }
    for (String source : w.bySource.keySet()) {
      if (!ids.contains(source)) {
        throw new IllegalArgumentException(
            "transition '"
                + w.bySource.get(source).get(0).id()
                + "' leaves '"
                + source
                + "', which is not a state of the definition");
      }
    }
    w.out.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    w.out
        .append("<scxml xmlns=\"")
        .append(Scxml.NAMESPACE)
        .append("\" xmlns:arm=\"")
        .append(Scxml.ARM_NAMESPACE)
        .append("\" version=\"1.0\" name=\"")
        .append(escape(definition.name()))
        .append('"');
    if (!definition.initial().isEmpty()) {
      w.out
          .append(" initial=\"")
          .append(escape(String.join(" ", definition.initial())))
          .append('"');
    }
    w.out.append(">\n");
    for (ScNode n : definition.states()) {
      w.node(n, 1);
    }
    w.out.append("</scxml>\n");
    return w.out.toString();
  }

  private static void collect(ScNode node, Set<String> ids) {
    ids.add(node.id());
    for (ScNode child : node.children()) {
      collect(child, ids);
    }
  }

  private void node(ScNode node, int depth) {
    String tag =
        switch (node.kind()) {
          case STATE -> "state";
          case PARALLEL -> "parallel";
          case FINAL -> "final";
          case SHALLOW_HISTORY, DEEP_HISTORY -> "history";
        };
    indent(depth).append('<').append(tag).append(" id=\"").append(escape(node.id())).append('"');
    boolean initialElement = !node.initial().isEmpty() && !node.defaultActions().isEmpty();
    if (!node.initial().isEmpty() && !initialElement) {
      out.append(" initial=\"").append(escape(String.join(" ", node.initial()))).append('"');
    }
    if (node.kind() == ScNode.Kind.DEEP_HISTORY) {
      out.append(" type=\"deep\"");
    }
    List<ScTransition> transitions = bySource.getOrDefault(node.id(), List.of());
    boolean empty =
        node.onEntry().isEmpty()
            && node.onExit().isEmpty()
            && node.historyDefault().isEmpty()
            && node.children().isEmpty()
            && node.doneData() == null
            && transitions.isEmpty();
    if (empty) {
      out.append("/>\n");
      return;
    }
    out.append(">\n");
    if (initialElement) {
      indent(depth + 1).append("<initial>\n");
      defaultTransition(node.initial(), node.defaultActions(), depth + 2);
      indent(depth + 1).append("</initial>\n");
    }
    content("onentry", node.onEntry(), depth + 1);
    content("onexit", node.onExit(), depth + 1);
    ScData done = node.doneData();
    if (done != null) {
      indent(depth + 1).append("<donedata>\n");
      data(done, depth + 2);
      indent(depth + 1).append("</donedata>\n");
    }
    if (!node.historyDefault().isEmpty()) {
      defaultTransition(node.historyDefault(), node.defaultActions(), depth + 1);
    }
    // The reader lists transitions in document order, so a state's own transitions go among its
    // children where that order puts them: before a child whose subtree has a later transition.
    List<Integer> own = places.getOrDefault(node.id(), List.of());
    int next = 0;
    for (ScNode child : node.children()) {
      int c = first(child);
      while (c >= 0 && next < transitions.size() && own.get(next) < c) {
        transition(transitions.get(next), next + 1, depth + 1);
        next++;
      }
      node(child, depth + 1);
    }
    for (; next < transitions.size(); next++) {
      transition(transitions.get(next), next + 1, depth + 1);
    }
    indent(depth).append("</").append(tag).append(">\n");
  }

  private void defaultTransition(List<String> targets, List<ScAction> actions, int depth) {
    indent(depth)
        .append("<transition target=\"")
        .append(escape(String.join(" ", targets)))
        .append('"');
    if (actions.isEmpty()) {
      out.append("/>\n");
      return;
    }
    out.append(">\n");
    actions(actions, depth + 1);
    indent(depth).append("</transition>\n");
  }

  private void transition(ScTransition t, int n, int depth) {
    indent(depth).append("<transition");
    if (!t.events().isEmpty()) {
      out.append(" event=\"").append(escape(String.join(" ", t.events()))).append('"');
    }
    if (t.cond() != null) {
      out.append(" cond=\"").append(escape(t.cond())).append('"');
    }
    if (!t.targets().isEmpty()) {
      out.append(" target=\"").append(escape(String.join(" ", t.targets()))).append('"');
    }
    if (t.internal()) {
      out.append(" type=\"internal\"");
    }
    if (!t.id().equals(Scxml.defaultTransitionId(t.source(), n))) {
      out.append(" arm:id=\"").append(escape(t.id())).append('"');
    }
    if (t.actions().isEmpty()) {
      out.append("/>\n");
      return;
    }
    out.append(">\n");
    actions(t.actions(), depth + 1);
    indent(depth).append("</transition>\n");
  }

  private void content(String tag, List<ScAction> actions, int depth) {
    if (actions.isEmpty()) {
      return;
    }
    indent(depth).append('<').append(tag).append(">\n");
    actions(actions, depth + 1);
    indent(depth).append("</").append(tag).append(">\n");
  }

  private void actions(List<ScAction> actions, int depth) {
    for (ScAction a : actions) {
      switch (a) {
        case ScAction.Run r ->
            indent(depth).append("<arm:action name=\"").append(escape(r.name())).append("\"/>\n");
        case ScAction.Raise r ->
            indent(depth).append("<raise event=\"").append(escape(r.event())).append("\"/>\n");
        case ScAction.Log l -> {
          indent(depth).append("<log");
          if (l.label() != null) {
            out.append(" label=\"").append(escape(l.label())).append('"');
          }
          if (l.expr() != null) {
            out.append(" expr=\"").append(escape(l.expr())).append('"');
          }
          out.append("/>\n");
        }
        case ScAction.Send send -> send(send, depth);
        case ScAction.If i -> {
          for (int b = 0; b < i.branches().size(); b++) {
            ScAction.Branch branch = i.branches().get(b);
            indent(depth)
                .append(b == 0 ? "<if" : "<elseif")
                .append(" cond=\"")
                .append(escape(branch.cond()))
                .append(b == 0 ? "\">\n" : "\"/>\n");
            actions(branch.actions(), depth + 1);
          }
          if (!i.otherwise().isEmpty()) {
            indent(depth).append("<else/>\n");
            actions(i.otherwise(), depth + 1);
          }
          indent(depth).append("</if>\n");
        }
      }
    }
  }

  private void send(ScAction.Send send, int depth) {
    indent(depth).append("<send");
    if (send.event() != null) {
      out.append(" event=\"").append(escape(send.event())).append('"');
    }
    if (send.eventExpr() != null) {
      out.append(" eventexpr=\"").append(escape(send.eventExpr())).append('"');
    }
    if (send.internal()) {
      out.append(" target=\"").append(Scxml.INTERNAL_TARGET).append('"');
    }
    ScData data = send.data();
    if (data == null) {
      out.append("/>\n");
      return;
    }
    out.append(">\n");
    data(data, depth + 1);
    indent(depth).append("</send>\n");
  }

  /** {@code <param>}s or a {@code <content>}. */
  private void data(ScData data, int depth) {
    switch (data) {
      case ScData.Params p -> {
        for (ScData.Param param : p.params()) {
          indent(depth)
              .append("<param name=\"")
              .append(escape(param.name()))
              .append("\" expr=\"")
              .append(escape(param.expr()))
              .append("\"/>\n");
        }
      }
      // The text as it is, white space included: a reader gives it back unchanged.
      case ScData.Text t ->
          indent(depth).append("<content>").append(escapeText(t.text())).append("</content>\n");
      case ScData.Expr e ->
          indent(depth).append("<content expr=\"").append(escape(e.expr())).append("\"/>\n");
    }
  }

  private StringBuilder indent(int depth) {
    return out.append("  ".repeat(depth));
  }

  /**
   * Text in an element: a parser keeps its white space but would turn a carriage return into a line
   * feed.
   */
  private static String escapeText(String s) {
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\r", "&#13;");
  }

  private static String escape(String s) {
    return s.replace("&", "&amp;")
        .replace("<", "&lt;")
        .replace(">", "&gt;")
        .replace("\"", "&quot;")
        .replace("'", "&apos;")
        // A parser turns these into spaces in an attribute's value; as references they stay.
        .replace("\t", "&#9;")
        .replace("\n", "&#10;")
        .replace("\r", "&#13;");
  }
}
