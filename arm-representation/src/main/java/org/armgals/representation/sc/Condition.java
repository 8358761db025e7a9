package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jspecify.annotations.Nullable;

/**
 * The condition language of {@code cond} (docs/representations.md): {@code true}, {@code false},
 * {@code In('id')}, comparisons ({@code == != === !== < <= > >=}) of {@code _event.name}, {@code
 * _event.data} and its fields ({@code _event.data.a.b}, looked up in maps) with string, number,
 * boolean and {@code null} literals, combined with {@code && || !} and parentheses. It is parsed
 * once and evaluated without a script engine; anything else is refused when parsed, naming the
 * construct.
 *
 * <p>Immutable and thread-safe.
 */
final class Condition {

  /** A parsed expression. */
  private sealed interface Expr {}

  private record Literal(@Nullable Object value) implements Expr {}

  private record EventName() implements Expr {}

  private record EventData(List<String> path) implements Expr {}

  private record In(String state) implements Expr {}

  private record Not(Expr operand) implements Expr {}

  private record And(Expr left, Expr right) implements Expr {}

  private record Or(Expr left, Expr right) implements Expr {}

  private record Compare(String op, Expr left, Expr right) implements Expr {}

  /**
   * What a condition is evaluated against: which states are active (for {@code In}), and the event
   * being processed.
   */
  record Context(
      Predicate<String> active, @Nullable String eventName, @Nullable Object eventData) {}

  private final String text;
  private final Expr expr;
  private final List<String> states;

  private Condition(String text, Expr expr, List<String> states) {
    this.text = text;
    this.expr = expr;
    this.states = List.copyOf(states);
  }

  /**
   * The condition {@code text} says.
   *
   * @throws IllegalArgumentException if it is not in the language, naming what is not
   */
  static Condition parse(String text) {
    requireNonNull(text, "text");
    Parser p = new Parser(text);
    Expr e = p.or();
    p.skipSpace();
    if (p.pos < text.length()) {
      String rest = text.substring(p.pos);
      Matcher op = ECMASCRIPT_OPERATOR.matcher(rest);
      throw p.error(
          op.lookingAt()
              ? "ECMAScript's operator '" + op.group().strip() + "' (in '" + rest + "')"
              : "'" + rest + "' after a complete condition");
    }
    return new Condition(text, e, p.states);
  }

  /** The state ids its {@code In()}s name. */
  List<String> states() {
    return states;
  }

  /**
   * Whether the condition holds in {@code context}: its value converted as ECMAScript's ToBoolean.
   */
  boolean holds(Context context) {
    return truthy(value(expr, context));
  }

  /**
   * The value of the expression in {@code context}: a string, a number, a boolean, null, {@link
   * #UNDEFINED}, or what the event's data holds.
   */
  @Nullable Object value(Context context) {
    return value(expr, context);
  }

  /**
   * {@code v} as ECMAScript's ToString writes a primitive value ({@code 'a'} is {@code a}, {@code
   * 2.50} is {@code 2.5}, {@code null} and {@code undefined} are their names); null for anything
   * else (a map, a list, another object).
   */
  static @Nullable String text(@Nullable Object v) {
    return switch (v) {
      case null -> "null";
      case Undefined u -> "undefined";
      case String s -> s;
      case Boolean b -> b.toString();
      case Double d when d.isNaN() || d.isInfinite() -> d > 0 ? "Infinity" : d.toString();
      case Float f when f.isNaN() || f.isInfinite() -> text(f.doubleValue());
      case Number n -> {
        BigDecimal b = new BigDecimal(n.toString()).stripTrailingZeros();
        yield b.signum() == 0 ? "0" : b.toPlainString();
      }
      default -> null;
    };
  }

  @Override
  public String toString() {
    return text;
  }

  /** ECMAScript's {@code undefined}: a missing field, or the name of an event not known. */
  private enum Undefined {
    UNDEFINED;

    @Override
    public String toString() {
      return "undefined";
    }
  }

  /** ECMAScript's {@code undefined}, as a value of an expression or in an event's data. */
  static final Object UNDEFINED = Undefined.UNDEFINED;

  private static @Nullable Object value(Expr e, Context c) {
    return switch (e) {
      case Literal l -> l.value();
      case EventName n -> c.eventName() == null ? UNDEFINED : c.eventName();
      case EventData d -> field(c.eventData(), d.path());
      case In in -> c.active().test(in.state());
      case Not n -> !truthy(value(n.operand(), c));
      // ECMAScript's && and || answer one of their operands.
      case And a -> {
        Object left = value(a.left(), c);
        yield truthy(left) ? value(a.right(), c) : left;
      }
      case Or o -> {
        Object left = value(o.left(), c);
        yield truthy(left) ? left : value(o.right(), c);
      }
      case Compare cmp -> compare(cmp.op(), value(cmp.left(), c), value(cmp.right(), c));
    };
  }

  /** {@code _event.data} and its fields: a missing field (or a field of a non-map) is undefined. */
  private static @Nullable Object field(@Nullable Object data, List<String> path) {
    Object v = data == null ? UNDEFINED : data;
    for (String key : path) {
      if (!(v instanceof Map<?, ?> m) || !m.containsKey(key)) {
        return UNDEFINED;
      }
      v = m.get(key);
    }
    return v;
  }

  /** ECMAScript's ToBoolean. */
  private static boolean truthy(@Nullable Object v) {
    return switch (v) {
      case null -> false;
      case Undefined u -> false;
      case Boolean b -> b;
      case Number n -> {
        double d = n.doubleValue();
        yield d != 0 && !Double.isNaN(d);
      }
      case String s -> !s.isEmpty();
      default -> true;
    };
  }

  private static boolean compare(String op, @Nullable Object a, @Nullable Object b) {
    return switch (op) {
      case "===" -> strictlyEqual(a, b);
      case "!==" -> !strictlyEqual(a, b);
      case "==" -> looselyEqual(a, b);
      case "!=" -> !looselyEqual(a, b);
      case "<" -> less(a, b, false);
      case ">" -> less(b, a, false);
      case "<=" -> less(a, b, true);
      default -> less(b, a, true);
    };
  }

  /** ECMAScript's {@code ===}; objects (maps, lists, anything else) compare by {@code equals}. */
  private static boolean strictlyEqual(@Nullable Object a, @Nullable Object b) {
    if (a instanceof Number x && b instanceof Number y) {
      return numeric(x.doubleValue(), y.doubleValue(), x, y) == 0;
    }
    if (a == null || b == null || a == UNDEFINED || b == UNDEFINED) {
      return a == b;
    }
    return a.equals(b);
  }

  /**
   * ECMAScript's {@code ==}: null and undefined are equal; numbers, strings and booleans convert.
   */
  private static boolean looselyEqual(@Nullable Object a, @Nullable Object b) {
    boolean aNil = a == null || a == UNDEFINED;
    boolean bNil = b == null || b == UNDEFINED;
    if (aNil || bNil) {
      return aNil && bNil;
    }
    if (a instanceof Boolean x) {
      return looselyEqual(x ? 1 : 0, b);
    }
    if (b instanceof Boolean y) {
      return looselyEqual(a, y ? 1 : 0);
    }
    if (a instanceof Number && b instanceof String || a instanceof String && b instanceof Number) {
      double x = number(a);
      double y = number(b);
      return x == y; // false for NaN
    }
    return strictlyEqual(a, b);
  }

  /**
   * ECMAScript's {@code a < b} ({@code a <= b} when {@code orEqual}): strings compare by their
   * UTF-16 code units, anything else as numbers, and NaN (undefined, a string that is no number, an
   * object) compares false.
   */
  private static boolean less(@Nullable Object a, @Nullable Object b, boolean orEqual) {
    if (a instanceof String x && b instanceof String y) {
      int c = x.compareTo(y);
      return orEqual ? c <= 0 : c < 0;
    }
    double x = number(a);
    double y = number(b);
    if (Double.isNaN(x) || Double.isNaN(y)) {
      return false;
    }
    int c = numeric(x, y, a, b);
    return orEqual ? c <= 0 : c < 0;
  }

  /** ECMAScript's ToNumber, for the values the language has. */
  private static double number(@Nullable Object v) {
    return switch (v) {
      case null -> 0;
      case Number n -> n.doubleValue();
      case Boolean b -> b ? 1 : 0;
      case String s -> {
        String t = s.strip();
        if (t.isEmpty()) {
          yield 0;
        }
        if (t.matches("0[xX][0-9a-fA-F]+")) {
          yield new java.math.BigInteger(t.substring(2), 16).doubleValue();
        }
        yield t.matches("[+-]?(\\d+\\.?\\d*([eE][+-]?\\d+)?|\\.\\d+([eE][+-]?\\d+)?|Infinity)")
            ? Double.parseDouble(t)
            : Double.NaN;
      }
      default -> Double.NaN; // undefined, and objects
    };
  }

  /**
   * Compares two numbers that are not NaN: exactly by value when both are finite Java numbers (so
   * that a {@code long} beyond a double's precision keeps it), else as doubles.
   */
  private static int numeric(double x, double y, @Nullable Object a, @Nullable Object b) {
    if (Double.isNaN(x) || Double.isNaN(y)) {
      return Double.isNaN(x) && Double.isNaN(y) ? 1 : -1; // never 0: NaN equals nothing
    }
    if (a instanceof Number p
        && b instanceof Number q
        && Double.isFinite(x)
        && Double.isFinite(y)) {
      return new BigDecimal(p.toString()).compareTo(new BigDecimal(q.toString()));
    }
    return Double.compare(x, y) == 0 || x == y ? 0 : Double.compare(x, y);
  }

  /** ECMAScript operators the language does not have, as they may follow a complete operand. */
  private static final Pattern ECMASCRIPT_OPERATOR =
      Pattern.compile("(\\+\\+|--|\\+|-|\\*|/|%|\\?|\\[|=(?!=)|\\bin\\b|\\binstanceof\\b)\\s*");

  /** ECMAScript's keywords that may begin an expression or a statement. */
  private static final Set<String> ECMASCRIPT_KEYWORDS =
      Set.of(
          "typeof",
          "void",
          "delete",
          "new",
          "this",
          "function",
          "return",
          "var",
          "let",
          "const",
          "in",
          "instanceof",
          "if",
          "for",
          "while");

  /** The system variables of the recommendation's data models (section 5.10). */
  private static final Set<String> SYSTEM_VARIABLES =
      Set.of("_sessionid", "_name", "_ioprocessors");

  /**
   * What {@code word}, an operand the language does not have, is: the message names it as what it
   * needs (ECMAScript, or a data model).
   */
  private static String describe(String word) {
    String head = word.contains(".") ? word.substring(0, word.indexOf('.')) : word;
    if (ECMASCRIPT_KEYWORDS.contains(word)) {
      return "ECMAScript's '" + word + "'";
    }
    if (word.equals("_event")) {
      return "'_event' (the data model's event variable; the language has its fields name and"
          + " data)";
    }
    if (head.equals("_event")) {
      return "'" + word + "' (a field of the data model's _event other than name and data)";
    }
    if (SYSTEM_VARIABLES.contains(head)) {
      return "'" + word + "' (a system variable of the data model)";
    }
    if (!word.isEmpty()
        && (Character.isLetter(word.charAt(0)) || word.charAt(0) == '_' || word.charAt(0) == '$')) {
      return "'" + word + "' (a variable of a data model)";
    }
    return "'" + word + "'";
  }

  /** A recursive-descent parser of the language. */
  private static final class Parser {
    private static final List<String> OPS = List.of("===", "!==", "==", "!=", "<=", ">=", "<", ">");
    final String text;
    int pos;
    final List<String> states = new ArrayList<>();

    Parser(String text) {
      this.text = text;
    }

    IllegalArgumentException error(String what) {
      return new IllegalArgumentException(
          "condition '"
              + text
              + "': "
              + what
              + " is not supported; expected true, false, In('id'), comparisons of _event.name"
              + " or _event.data fields with literals, && || ! and parentheses");
    }

    void skipSpace() {
      while (pos < text.length() && Character.isWhitespace(text.charAt(pos))) {
        pos++;
      }
    }

    boolean eat(String token) {
      skipSpace();
      if (text.startsWith(token, pos)) {
        pos += token.length();
        return true;
      }
      return false;
    }

    Expr or() {
      Expr left = and();
      while (eat("||")) {
        left = new Or(left, and());
      }
      return left;
    }

    Expr and() {
      Expr left = unary();
      while (eat("&&")) {
        left = new And(left, unary());
      }
      return left;
    }

    Expr unary() {
      skipSpace();
      if (text.startsWith("!", pos) && !text.startsWith("!=", pos)) {
        pos++;
        return new Not(unary());
      }
      Expr left = primary();
      skipSpace();
      for (String op : OPS) {
        if (text.startsWith(op, pos)) {
          pos += op.length();
          Expr right = primary();
          if (left instanceof Compare || right instanceof Compare) {
            throw error("a chained comparison");
          }
          return new Compare(op, left, right);
        }
      }
      return left;
    }

    Expr primary() {
      skipSpace();
      if (pos >= text.length()) {
        throw error("an empty operand at the end");
      }
      char c = text.charAt(pos);
      if (c == '(') {
        pos++;
        Expr e = or();
        if (!eat(")")) {
          throw error("a '(' without its ')'");
        }
        return e;
      }
      if (c == '\'' || c == '"') {
        return new Literal(string(c));
      }
      if (Character.isDigit(c) || c == '-' || c == '.') {
        return new Literal(number());
      }
      String word = word();
      return switch (word) {
        case "true" -> new Literal(Boolean.TRUE);
        case "false" -> new Literal(Boolean.FALSE);
        case "null" -> new Literal(null);
        case "undefined" -> new Literal(UNDEFINED);
        case "In" -> in();
        case "_event.name" -> new EventName();
        case "_event.data" -> new EventData(List.of());
        default -> {
          if (word.startsWith("_event.data.")) {
            List<String> path = List.of(word.substring("_event.data.".length()).split("\\."));
            if (path.stream().anyMatch(String::isEmpty)) {
              throw error("'" + word + "'");
            }
            yield new EventData(path);
          }
          if (word.isEmpty()) {
            Matcher op = ECMASCRIPT_OPERATOR.matcher(text).region(pos, text.length());
            throw error(
                op.lookingAt()
                    ? "ECMAScript's operator '" + op.group().strip() + "'"
                    : "'" + text.substring(pos) + "'");
          }
          throw error(describe(word));
        }
      };
    }

    private Expr in() {
      if (!eat("(")) {
        throw error("In without '('");
      }
      skipSpace();
      String id;
      if (pos < text.length() && (text.charAt(pos) == '\'' || text.charAt(pos) == '"')) {
        id = string(text.charAt(pos));
      } else {
        int close = text.indexOf(')', pos);
        id = text.substring(pos, close < 0 ? text.length() : close).strip();
        pos = close < 0 ? text.length() : close;
      }
      if (!eat(")")) {
        throw error("In(" + id + " without ')'");
      }
      try {
        ScNames.requireName(id, "state of In()");
      } catch (IllegalArgumentException e) {
        throw error("In('" + id + "')");
      }
      states.add(id);
      return new In(id);
    }

    private String word() {
      int start = pos;
      while (pos < text.length()) {
        char c = text.charAt(pos);
        if (Character.isLetterOrDigit(c) || c == '_' || c == '.' || c == '$') {
          pos++;
        } else {
          break;
        }
      }
      return text.substring(start, pos);
    }

    private String string(char quote) {
      int end = text.indexOf(quote, pos + 1);
      if (end < 0) {
        throw error("an unterminated string");
      }
      String s = text.substring(pos + 1, end);
      if (s.indexOf('\\') >= 0) {
        throw error("an escape in '" + s + "'");
      }
      pos = end + 1;
      return s;
    }

    private BigDecimal number() {
      int start = pos;
      if (text.charAt(pos) == '-') {
        pos++;
      }
      while (pos < text.length()
          && (Character.isDigit(text.charAt(pos)) || text.charAt(pos) == '.')) {
        pos++;
      }
      String n = text.substring(start, pos);
      try {
        return new BigDecimal(n);
      } catch (NumberFormatException e) {
        throw error("the number '" + n + "'");
      }
    }
  }
}
