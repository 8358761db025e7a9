package org.armgals.representation.sc;

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
   * An element as parsed: namespace, local name, attributes, children, line, and the line of the
   * first text it holds directly (-1 for none; white space is not text).
   */
  private record El(
      String ns, String name, Map<String, String> attrs, List<El> children, int line, int[] text) {
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
      Set<String> allowed = Set.of(keys);
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
      El el = new El(uri, local, attrs, new ArrayList<>(), line(), new int[] {-1});
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
      if (!stack.isEmpty() && !new String(ch, start, length).isBlank()) {
        int[] text = stack.get(stack.size() - 1).text();
        if (text[0] < 0) {
          text[0] = line();
        }
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
          () -> new ScNode(id, k, init, onEntry, onExit, historyDefault, children, defaultActions));
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
        if (el.ns().equals(Scxml.NAMESPACE) && el.name().equals("raise")) {
          el.allow("event");
          String event = el.required("event");
          actions.add(guarded(el, () -> ScAction.raise(event)));
        } else if (el.ns().equals(Scxml.NAMESPACE) && el.name().equals("log")) {
          el.allow("label", "expr");
          String label = el.attr("label");
          String expr = el.attr("expr");
          actions.add(guarded(el, () -> ScAction.log(label, expr == null ? null : expr.strip())));
        } else if (el.ns().equals(Scxml.ARM_NAMESPACE) && el.name().equals("action")) {
          el.allow("name");
          String name = el.required("name");
          actions.add(guarded(el, () -> ScAction.run(name)));
        } else {
          throw unsupported(el, "<raise>, <log> and <arm:action>");
        }
        if (!el.children().isEmpty()) {
          throw new ScxmlException("<" + el.tag() + "> must be empty", el.line());
        }
      }
      return actions;
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
