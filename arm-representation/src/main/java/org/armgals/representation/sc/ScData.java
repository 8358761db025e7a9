package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.Arrays;
import java.util.List;

/**
 * The data an event carries, as a {@link ScAction.Send} or a final state's {@code <donedata>} gives
 * it (SCXML {@code <param>} children or one {@code <content>}). It is evaluated when the send runs
 * or the final state is entered, and conditions see it as {@code _event.data}
 * (docs/representations.md).
 *
 * <p>Every expression is in the condition language, evaluated without a data model: a value such as
 * {@code 'on'}, {@code 12}, {@code _event.data.speed} or a condition.
 */
public sealed interface ScData {

  /**
   * Names with values ({@code <param name="..." expr="..."/>}, in order): {@code _event.data} is a
   * map of each name to its value; of two params of one name, the later gives the value.
   *
   * @param params at least one
   */
  record Params(List<Param> params) implements ScData {
    /**
     * Copies the list.
     *
     * @throws IllegalArgumentException if it is empty
     */
    public Params {
      params = List.copyOf(requireNonNull(params, "params"));
      if (params.isEmpty()) {
        throw new IllegalArgumentException("no param; expected at least one");
      }
    }
  }

  /**
   * One name and the expression of its value ({@code <param name="..." expr="..."/>}).
   *
   * @param name the key in {@code _event.data}; not blank
   * @param expr its value, in the condition language
   */
  record Param(String name, String expr) {
    /**
     * Checks the name and the expression.
     *
     * @throws IllegalArgumentException if the name is blank or the expression is not in the
     *     condition language
     */
    public Param {
      requireNonNull(name, "name");
      if (name.isBlank()) {
        throw new IllegalArgumentException("param name is blank; expected a name");
      }
      Condition.parse(requireNonNull(expr, "expr"));
    }
  }

  /**
   * Text ({@code <content>text</content>}), read as ECMAScript's data model reads it: JSON (an
   * object, an array, a string, a number, {@code true}, {@code false}, {@code null}) gives that
   * value, anything else the text space-normalized (trimmed, each run of white space one space).
   *
   * @param text as written, white space included
   */
  record Text(String text) implements ScData {
    /** Checks the text is present. */
    public Text {
      requireNonNull(text, "text");
    }
  }

  /**
   * An expression whose value is the data ({@code <content expr="..."/>}).
   *
   * @param expr in the condition language
   */
  record Expr(String expr) implements ScData {
    /**
     * Checks the expression.
     *
     * @throws IllegalArgumentException if it is not in the condition language
     */
    public Expr {
      Condition.parse(requireNonNull(expr, "expr"));
    }
  }

  /** A {@link Param} of {@code name} whose value is {@code expr}. */
  static Param param(String name, String expr) {
    return new Param(name, expr);
  }

  /** {@link Params} of these params, in order. */
  static ScData params(Param... params) {
    return new Params(Arrays.asList(params));
  }

  /** {@link Text} of {@code text}. */
  static ScData text(String text) {
    return new Text(text);
  }

  /** {@link Expr} of {@code expr}. */
  static ScData expr(String expr) {
    return new Expr(expr);
  }
}
