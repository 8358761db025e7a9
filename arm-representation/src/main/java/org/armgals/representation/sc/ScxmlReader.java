package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParserFactory;
import org.jspecify.annotations.Nullable;
import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/** Reads the supported subset of SCXML into a definition; see {@link Scxml}. */
final class ScxmlReader {
  private ScxmlReader() {}

  /**
   * An element as parsed: namespace, local name, attributes, children, line, the line of the first
   * text it holds directly (-1 for none; white space is not text), and that text, white space
   * included.
   */
  private record El(
      String ns,
      String name,
      Map<String, String> attrs,
      List<El> children,
      int line,
      int[] text,
      StringBuilder chars) {
    String tag() {
      return ns.equals(Scxml.ARM_NAMESPACE) ? "arm:" + name : name;
    }

    @Nullable String attr(String key) {
      return attrs.get(key);
    }

    String required(String key) {
      String value = attrs.get(key);
      if (value == null || value.isBlank()) {
        throw new ScxmlException("<" + tag() + "> has no " + key + "; expected one", line);
      }
      return value.strip();
    }

    /** Refuses attributes other than {@code keys}, and text: every supported element says so. */
    void allow(String... keys) {
      if (text[0] >= 0) {
        throw new ScxmlException(
            "text in <" + tag() + "> is not supported; expected elements only", text[0]);
      }
      attributes(keys);
    }

    /** Refuses attributes other than {@code keys}. */
    void attributes(String... keys) {
      // A list, so that the message names them in the same order in every run.
      List<String> allowed = List.of(keys);
      for (String key : attrs.keySet()) {
        if (!allowed.contains(key)) {
          throw new ScxmlException(
              "attribute '" + key + "' of <" + tag() + "> is not supported; supported: " + allowed,
              line);
        }
      }
    }
  }

  private static final class Builder extends DefaultHandler {
    private @Nullable Locator locator;
    private final List<El> stack = new ArrayList<>();
    private @Nullable El root;

    @Override
    public void setDocumentLocator(Locator locator) {
      this.locator = locator;
    }

    private int line() {
      return locator == null ? -1 : locator.getLineNumber();
    }

    @Override
    public void startElement(String uri, String local, String qName, Attributes attributes) {
      Map<String, String> attrs = new LinkedHashMap<>();
      for (int i = 0; i < attributes.getLength(); i++) {
        String ns = attributes.getURI(i);
        String name = attributes.getLocalName(i);
        attrs.put(ns.equals(Scxml.ARM_NAMESPACE) ? "arm:" + name : name, attributes.getValue(i));
      }
      El el =
          new El(uri, local, attrs, new ArrayList<>(), line(), new int[] {-1}, new StringBuilder());
      if (stack.isEmpty()) {
        root = el;
      } else {
        stack.get(stack.size() - 1).children().add(el);
      }
      stack.add(el);
    }

    @Override
    public void endElement(String uri, String local, String qName) {
      stack.remove(stack.size() - 1);
    }

    @Override
    public void characters(char[] ch, int start, int length) {
      // Text is refused when its element is converted, so that an unsupported element holding
      // text (<data>, <content>, <script>) is refused as such, and text in a supported one is
      // named with its element.
      if (stack.isEmpty()) {
        return;
      }
      El el = stack.get(stack.size() - 1);
      el.chars().append(ch, start, length);
      if (el.text()[0] < 0 && !new String(ch, start, length).isBlank()) {
        el.text()[0] = line();
      }
    }
  }

  static ScDefinition read(Reader reader) {
    Builder builder = new Builder();
    try {
      SAXParserFactory factory = SAXParserFactory.newInstance();
      factory.setNamespaceAware(true);
      factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
      factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
      factory.newSAXParser().parse(new InputSource(reader), builder);
    } catch (SAXParseException e) {
      throw new ScxmlException("malformed SCXML: " + e.getMessage(), e.getLineNumber());
    } catch (SAXException | ParserConfigurationException | IOException e) {
      throw new ScxmlException("cannot read SCXML: " + e.getMessage(), -1);
    }
    El root = builder.root;
    if (root == null) {
      throw new ScxmlException("empty document; expected <scxml>", -1);
    }
    return new ScxmlReader.Conversion().definition(root);
  }

  /** What a guard's name looks like in {@code cond}: a Java identifier. */
  private static final Pattern GUARD_NAME = Pattern.compile("[A-Za-z_$][A-Za-z0-9_$]*");

  /** From parsed elements to the definition's records. */
  private static final class Conversion {
    private final List<ScTransition> transitions = new ArrayList<>();

    ScDefinition definition(El scxml) {
      if (!scxml.ns().equals(Scxml.NAMESPACE) || !scxml.name().equals("scxml")) {
        throw new ScxmlException(
            "root element <"
                + scxml.tag()
                + "> (namespace '"
                + scxml.ns()
                + "') is not <scxml> of "
                + Scxml.NAMESPACE,
            scxml.line());
      }
      scxml.allow("initial", "name", "version", "datamodel");
      String datamodel = scxml.attr("datamodel");
      if (datamodel != null && !Set.of("null", "ecmascript").contains(datamodel.strip())) {
        throw new ScxmlException(
            "datamodel '"
                + datamodel
                + "' is not supported; expected none, 'null' or 'ecmascript' (whose conditions"
                + " must then be in the condition language)",
            scxml.line());
      }
      String version = scxml.attr("version");
      if (version != null && !version.strip().equals("1.0")) {
        throw new ScxmlException(
            "version '" + version + "' is not supported; expected 1.0", scxml.line());
      }
      List<ScNode> states = new ArrayList<>();
      for (El child : scxml.children()) {
        switch (scxmlName(child)) {
          case "state", "parallel", "final" -> states.add(node(child));
          default -> throw unsupported(child, "<state>, <parallel>, <final>");
        }
      }
      String name = scxml.attr("name");
      return guarded(
          scxml,
          () ->
              new ScDefinition(
                  name == null ? "statechart" : name.strip(),
                  tokens(scxml.attr("initial")),
                  states,
                  transitions));
    }

    private ScNode node(El el) {
      String kind = scxmlName(el);
      switch (kind) {
        case "state" -> el.allow("id", "initial");
        case "history" -> el.allow("id", "type");
        default -> el.allow("id");
      }
      String id = el.required("id");
      List<String> initial = kind.equals("state") ? tokens(el.attr("initial")) : List.of();
      List<ScAction> onEntry = new ArrayList<>();
      List<ScAction> onExit = new ArrayList<>();
      List<String> historyDefault = new ArrayList<>();
      List<ScAction> defaultActions = new ArrayList<>();
      List<ScNode> children = new ArrayList<>();
      ScData[] doneData = {null};
      int transitionCount = 0;
      for (El child : el.children()) {
        String name = scxmlName(child);
        switch (kind + "/" + name) {
          case "state/onentry", "parallel/onentry", "final/onentry" -> {
            child.allow();
            onEntry.addAll(content(child));
          }
          case "state/onexit", "parallel/onexit", "final/onexit" -> {
            child.allow();
            onExit.addAll(content(child));
          }
          case "final/donedata" -> {
            if (doneData[0] != null) {
              throw new ScxmlException(
                  "<final id=\"" + id + "\"> has a second <donedata>; expected at most one",
                  child.line());
            }
            child.allow();
            doneData[0] = data(child);
          }
          case "state/transition", "parallel/transition" ->
              transitions.add(transition(child, id, ++transitionCount));
          case "state/state",
              "state/parallel",
              "state/final",
              "state/history",
              "parallel/state",
              "parallel/parallel",
              "parallel/history" ->
              children.add(node(child));
          case "state/initial" -> {
            if (!initial.isEmpty()) {
              throw new ScxmlException(
                  "<state id=\"" + id + "\"> has both an initial attribute and <initial>",
                  child.line());
            }
            initial = initialChild(child);
            defaultActions.addAll(content(child.children().get(0)));
          }
          case "history/transition" -> {
            if (!historyDefault.isEmpty()) {
              throw new ScxmlException(
                  "<history id=\"" + id + "\"> has a second <transition>; expected at most one",
                  child.line());
            }
            historyDefault.addAll(targetOnly(child));
            defaultActions.addAll(content(child));
          }
          default ->
              throw unsupported(child, "what SCXML allows in <" + kind + "> among the subset");
        }
      }
      ScNode.Kind k =
          switch (kind) {
            case "state" -> ScNode.Kind.STATE;
            case "parallel" -> ScNode.Kind.PARALLEL;
            case "final" -> ScNode.Kind.FINAL;
            default -> historyKind(el);
          };
      List<String> init = initial;
      return guarded(
          el,
          () ->
              new ScNode(
                  id,
                  k,
                  init,
                  onEntry,
                  onExit,
                  historyDefault,
                  children,
                  defaultActions,
                  doneData[0]));
    }

    private static ScNode.Kind historyKind(El el) {
      String type = el.attr("type");
      if (type == null || type.strip().equals("shallow")) {
        return ScNode.Kind.SHALLOW_HISTORY;
      }
      if (type.strip().equals("deep")) {
        return ScNode.Kind.DEEP_HISTORY;
      }
      throw new ScxmlException(
          "history type '" + type + "' is not supported; expected 'shallow' or 'deep'", el.line());
    }

    private static List<String> initialChild(El initial) {
      initial.allow();
      if (initial.children().size() != 1
          || !scxmlName(initial.children().get(0)).equals("transition")) {
        throw new ScxmlException("<initial> must hold exactly one <transition>", initial.line());
      }
      return targetOnly(initial.children().get(0));
    }

    /**
     * The targets of a default transition (in initial and history), which has no event, condition
     * or type; its content is read by {@link #content}.
     */
    private static List<String> targetOnly(El transition) {
      transition.allow("target");
      return List.of(transition.required("target").split("\\s+"));
    }

    private ScTransition transition(El el, String source, int n) {
      el.allow("event", "cond", "target", "type", "arm:id");
      String id = el.attr("arm:id");
      String event = el.attr("event");
      String target = el.attr("target");
      String type = el.attr("type");
      boolean internal;
      if (type == null || type.strip().equals("external")) {
        internal = false;
      } else if (type.strip().equals("internal")) {
        internal = true;
      } else {
        throw new ScxmlException(
            "transition type '" + type + "' is not supported; expected 'internal' or 'external'",
            el.line());
      }
      List<ScAction> actions = content(el);
      String cond = condition(el);
      return guarded(
          el,
          () ->
              new ScTransition(
                  id == null ? Scxml.defaultTransitionId(source, n) : id.strip(),
                  source,
                  tokens(event),
                  cond == null ? null : cond.strip(),
                  tokens(target),
                  internal,
                  actions));
    }

    /**
     * The {@code cond} of a transition, if it is in the condition language or the name of a guard;
     * anything else (an ECMAScript expression beyond the language) is refused here, with the
     * construct and the line.
     */
    private static @Nullable String condition(El transition) {
      String cond = transition.attr("cond");
      if (cond == null) {
        return null;
      }
      String text = cond.strip();
      try {
        Condition.parse(text);
      } catch (IllegalArgumentException e) {
        if (!GUARD_NAME.matcher(text).matches()) {
          throw new ScxmlException(
              "cond of <transition> is neither a guard's name nor in the condition language: "
                  + e.getMessage(),
              transition.line());
        }
      }
      return text;
    }

    private static List<String> tokens(@Nullable String value) {
      return value == null || value.isBlank() ? List.of() : List.of(value.strip().split("\\s+"));
    }

    private static List<ScAction> content(El parent) {
      List<ScAction> actions = new ArrayList<>();
      for (El el : parent.children()) {
        actions.add(action(el));
      }
      return actions;
    }

    /** One element of executable content. */
    private static ScAction action(El el) {
      boolean scxml = el.ns().equals(Scxml.NAMESPACE);
      String name = scxml || el.ns().equals(Scxml.ARM_NAMESPACE) ? el.tag() : "";
      ScAction action =
          switch (name) {
            case "send" -> send(el);
            case "if" -> conditional(el);
            case "raise" -> {
              el.allow("event");
              String event = el.required("event");
              yield guarded(el, () -> ScAction.raise(event));
            }
            case "log" -> {
              el.allow("label", "expr");
              String label = el.attr("label");
              String expr = el.attr("expr");
              yield guarded(el, () -> ScAction.log(label, expr == null ? null : expr.strip()));
            }
            case "arm:action" -> {
              el.allow("name");
              String run = el.required("name");
              yield guarded(el, () -> ScAction.run(run));
            }
            default -> throw unsupported(el, "<raise>, <send>, <if>, <log> and <arm:action>");
          };
      if (action instanceof ScAction.Raise
          || action instanceof ScAction.Log
          || action instanceof ScAction.Run) {
        if (!el.children().isEmpty()) {
          throw new ScxmlException("<" + el.tag() + "> must be empty", el.line());
        }
      }
      return action;
    }

    /**
     * {@code <send>} to the chart itself without delay. What the subset leaves out is refused
     * naming it: a delay, another target, another I/O processor, what needs a data model.
     */
    private static ScAction send(El el) {
      for (String delay : List.of("delay", "delayexpr")) {
        if (el.attr(delay) != null) {
          throw new ScxmlException(
              "<send> with a delay ('"
                  + delay
                  + "') is not supported; expected a send without delay to the chart itself",
              el.line());
        }
      }
      String target = el.attr("target");
      if (target != null && !target.strip().equals(Scxml.INTERNAL_TARGET)) {
        throw new ScxmlException(
            "target '"
                + target
                + "' of <send> is not supported: the subset sends to the chart itself only (no"
                + " target: its external queue; '"
                + Scxml.INTERNAL_TARGET
                + "': its internal queue), not to other sessions, #_parent, invoked services or"
                + " other I/O processors",
            el.line());
      }
      if (el.attr("targetexpr") != null) {
        throw new ScxmlException(
            "targetexpr of <send> is not supported: a target computed at run time may name another"
                + " session; expected no target or '"
                + Scxml.INTERNAL_TARGET
                + "'",
            el.line());
      }
      String type = el.attr("type");
      if (type != null && !type.strip().equals(Scxml.SCXML_PROCESSOR)) {
        throw new ScxmlException(
            "type '"
                + type
                + "' of <send> is not supported; expected the SCXML event I/O processor ("
                + Scxml.SCXML_PROCESSOR
                + ", the default)",
            el.line());
      }
      if (el.attr("typeexpr") != null) {
        throw new ScxmlException(
            "typeexpr of <send> is not supported; expected no type or " + Scxml.SCXML_PROCESSOR,
            el.line());
      }
      for (String located : List.of("namelist", "idlocation")) {
        if (el.attr(located) != null) {
          throw new ScxmlException(
              located
                  + " of <send> names locations of a data model, which the subset does not have",
              el.line());
        }
      }
      if (el.attr("id") != null) {
        throw new ScxmlException(
            "id of <send> is not supported: a send id serves <cancel> of a delayed send and"
                + " _event.sendid, which the subset does not have",
            el.line());
      }
      el.allow("event", "eventexpr", "target", "type");
      String event = el.attr("event");
      String eventExpr = expression(el, "eventexpr");
      ScData data = data(el);
      return guarded(
          el,
          () ->
              new ScAction.Send(
                  event == null ? null : event.strip(), eventExpr, target != null, data));
    }

    /** The {@code <param>}s or the {@code <content>} of a {@code <send>} or {@code <donedata>}. */
    private static @Nullable ScData data(El parent) {
      List<ScData.Param> params = new ArrayList<>();
      ScData content = null;
      for (El child : parent.children()) {
        switch (scxmlName(child)) {
          case "param" -> params.add(param(child));
          case "content" -> {
            if (content != null) {
              throw new ScxmlException(
                  "<" + parent.tag() + "> has a second <content>; expected at most one",
                  child.line());
            }
            content = contentData(child);
          }
          default -> throw unsupported(child, "<param> or <content>");
        }
        if (content != null && !params.isEmpty()) {
          throw new ScxmlException(
              "<" + parent.tag() + "> has both <param> and <content>; expected one or the other",
              child.line());
        }
      }
      return content != null ? content : params.isEmpty() ? null : new ScData.Params(params);
    }

    private static ScData.Param param(El el) {
      if (el.attr("location") != null) {
        throw new ScxmlException(
            "location of <param> names a location of a data model, which the subset does not"
                + " have; expected expr",
            el.line());
      }
      el.allow("name", "expr");
      if (!el.children().isEmpty()) {
        throw new ScxmlException("<param> must be empty", el.line());
      }
      String name = el.required("name");
      String expr = expression(el, "expr");
      if (expr == null) {
        throw new ScxmlException("<param> has no expr; expected one", el.line());
      }
      return guarded(el, () -> new ScData.Param(name, expr));
    }

    private static ScData contentData(El el) {
      el.attributes("expr");
      if (!el.children().isEmpty()) {
        throw new ScxmlException(
            "XML in <content> is not supported (ECMAScript's data model would make it a DOM);"
                + " expected text or expr",
            el.children().get(0).line());
      }
      String expr = expression(el, "expr");
      if (expr == null) {
        return new ScData.Text(el.chars().toString());
      }
      if (el.text()[0] >= 0) {
        throw new ScxmlException(
            "<content> has both expr and text; expected one or the other", el.text()[0]);
      }
      return new ScData.Expr(expr);
    }

    /**
     * {@code <if>}, its {@code <elseif>}s and its {@code <else>}: the content between two of them
     * is the branch of the first.
     */
    private static ScAction conditional(El el) {
      el.allow("cond");
      List<ScAction.Branch> branches = new ArrayList<>();
      String cond = requiredExpression(el, "cond");
      List<ScAction> actions = new ArrayList<>();
      List<ScAction> otherwise = null;
      for (El child : el.children()) {
        boolean elseif = child.ns().equals(Scxml.NAMESPACE) && child.name().equals("elseif");
        boolean orElse = child.ns().equals(Scxml.NAMESPACE) && child.name().equals("else");
        if (!elseif && !orElse) {
          actions.add(action(child));
          continue;
        }
        if (otherwise != null) {
          throw new ScxmlException(
              "<" + child.name() + "> after <else> in <if>; expected <else> last", child.line());
        }
        child.allow(elseif ? new String[] {"cond"} : new String[0]);
        if (!child.children().isEmpty()) {
          throw new ScxmlException("<" + child.name() + "> must be empty", child.line());
        }
        String branchCond = cond;
        List<ScAction> branchActions = actions;
        branches.add(guarded(child, () -> new ScAction.Branch(branchCond, branchActions)));
        actions = new ArrayList<>();
        if (elseif) {
          cond = requiredExpression(child, "cond");
        } else {
          otherwise = actions;
        }
      }
      if (otherwise == null) {
        String lastCond = cond;
        List<ScAction> lastActions = actions;
        branches.add(guarded(el, () -> new ScAction.Branch(lastCond, lastActions)));
      }
      List<ScAction> orElse = otherwise == null ? List.of() : otherwise;
      return guarded(el, () -> new ScAction.If(branches, orElse));
    }

    private static String requiredExpression(El el, String attribute) {
      el.required(attribute);
      return requireNonNull(expression(el, attribute));
    }

    /**
     * The value of {@code attribute}, stripped, if it is in the condition language; null when
     * absent. Anything else (ECMAScript beyond the language, a data model's variable) is refused
     * here, with the construct and the line.
     */
    private static @Nullable String expression(El el, String attribute) {
      String value = el.attr(attribute);
      if (value == null) {
        return null;
      }
      String text = value.strip();
      try {
        Condition.parse(text);
      } catch (IllegalArgumentException e) {
        throw new ScxmlException(
            attribute
                + " of <"
                + el.tag()
                + "> is not in the condition language: "
                + e.getMessage(),
            el.line());
      }
      return text;
    }

    /** The SCXML local name of {@code el}, refusing elements of other namespaces. */
    private static String scxmlName(El el) {
      if (!el.ns().equals(Scxml.NAMESPACE)) {
        throw unsupported(el, "SCXML elements here");
      }
      return el.name();
    }

    private static ScxmlException unsupported(El el, String expected) {
      return new ScxmlException(
          "element <" + el.tag() + "> is not supported here; expected " + expected, el.line());
    }

    /** Runs a record's constructor, turning its complaint into an error with the line. */
    private static <T> T guarded(El el, Supplier<T> make) {
      try {
        return make.get();
      } catch (IllegalArgumentException e) {
        throw new ScxmlException("<" + el.tag() + ">: " + e.getMessage(), el.line());
      }
    }
  }
}
