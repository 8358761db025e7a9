package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
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

  /** What a condition is evaluated against. */
  record Context(
      Configuration configuration, @Nullable String eventName, @Nullable Object eventData) {}

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
      throw p.error("'" + text.substring(p.pos) + "' after a complete condition");
    }
    return new Condition(text, e, p.states);
  }

  /** The state ids its {@code In()}s name. */
  List<String> states() {
    return states;
  }

  /** Whether the condition holds in {@code context}. */
  boolean holds(Context context) {
    return Boolean.TRUE.equals(value(expr, context));
  }

  @Override
  public String toString() {
    return text;
  }

  private static @Nullable Object value(Expr e, Context c) {
    return switch (e) {
      case Literal l -> l.value();
      case EventName n -> c.eventName();
      case EventData d -> field(c.eventData(), d.path());
      case In in -> c.configuration().isActive(in.state());
      case Not n -> !Boolean.TRUE.equals(value(n.operand(), c));
      case And a ->
          Boolean.TRUE.equals(value(a.left(), c)) && Boolean.TRUE.equals(value(a.right(), c));
      case Or o ->
          Boolean.TRUE.equals(value(o.left(), c)) || Boolean.TRUE.equals(value(o.right(), c));
      case Compare cmp -> compare(cmp.op(), value(cmp.left(), c), value(cmp.right(), c));
    };
  }

  private static @Nullable Object field(@Nullable Object data, List<String> path) {
    Object v = data;
    for (String key : path) {
      if (!(v instanceof Map<?, ?> m)) {
        return null;
      }
      v = m.get(key);
    }
    return v;
  }

  private static boolean compare(String op, @Nullable Object a, @Nullable Object b) {
    if (a instanceof Number x && b instanceof Number y) {
      int c = numeric(x, y);
      return switch (op) {
        case "==", "===" -> c == 0;
        case "!=", "!==" -> c != 0;
        case "<" -> c < 0;
        case "<=" -> c <= 0;
        case ">" -> c > 0;
        default -> c >= 0;
      };
    }
    return switch (op) {
      case "==", "===" -> Objects.equals(a, b);
      case "!=", "!==" -> !Objects.equals(a, b);
      default -> {
        if (a instanceof String x && b instanceof String y) {
          int c = x.compareTo(y);
          yield switch (op) {
            case "<" -> c < 0;
            case "<=" -> c <= 0;
            case ">" -> c > 0;
            default -> c >= 0;
          };
        }
        yield false;
      }
    };
  }

  private static int numeric(Number x, Number y) {
    try {
      return new BigDecimal(x.toString()).compareTo(new BigDecimal(y.toString()));
    } catch (NumberFormatException e) {
      return Double.compare(x.doubleValue(), y.doubleValue()); // NaN and the infinities
    }
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
        case "null", "undefined" -> new Literal(null);
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
          throw error(word.isEmpty() ? "'" + text.substring(pos) + "'" : "'" + word + "'");
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
