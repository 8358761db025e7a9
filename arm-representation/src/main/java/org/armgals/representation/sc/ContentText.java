package org.armgals.representation.sc;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jspecify.annotations.Nullable;

/**
 * The value of {@code <content>} text as ECMAScript's data model reads it (the recommendation's
 * appendix B.2): JSON (RFC 8259) gives the value it denotes (an object as an unmodifiable {@code
 * Map} in the document's order, an array as a {@code List}, a number as a {@code BigDecimal}, a
 * string, a boolean, {@code null}); any other text gives the text space-normalized.
 */
final class ContentText {
  private final String text;
  private int pos;

  private ContentText(String text) {
    this.text = text;
  }

  /** The value of {@code text}. */
  static @Nullable Object value(String text) {
    ContentText json = new ContentText(text);
    try {
      Object v = json.value();
      json.space();
      if (json.pos == text.length()) {
        return v;
      }
    } catch (NotJson e) {
      // Not JSON: the text itself, below.
    }
    return String.join(" ", text.strip().split("\\s+"));
  }

  /** Thrown where the text stops being JSON; cheap, as it only says so. */
  private static final class NotJson extends Exception {
    private static final long serialVersionUID = 1L;

    NotJson() {
      super(null, null, false, false);
    }
  }

  private @Nullable Object value() throws NotJson {
    space();
    if (pos >= text.length()) {
      throw new NotJson();
    }
    char c = text.charAt(pos);
    return switch (c) {
      case '{' -> object();
      case '[' -> array();
      case '"' -> string();
      case 't' -> word("true", Boolean.TRUE);
      case 'f' -> word("false", Boolean.FALSE);
      case 'n' -> word("null", null);
      default -> number();
    };
  }

  private Map<String, @Nullable Object> object() throws NotJson {
    pos++;
    Map<String, @Nullable Object> members = new LinkedHashMap<>();
    space();
    if (eat('}')) {
      return Collections.unmodifiableMap(members);
    }
    do {
      space();
      if (pos >= text.length() || text.charAt(pos) != '"') {
        throw new NotJson();
      }
      String key = string();
      space();
      if (!eat(':')) {
        throw new NotJson();
      }
      members.put(key, value());
      space();
    } while (eat(','));
    if (!eat('}')) {
      throw new NotJson();
    }
    return Collections.unmodifiableMap(members);
  }

  private List<@Nullable Object> array() throws NotJson {
    pos++;
    List<@Nullable Object> items = new ArrayList<>();
    space();
    if (eat(']')) {
      return Collections.unmodifiableList(items);
    }
    do {
      items.add(value());
      space();
    } while (eat(','));
    if (!eat(']')) {
      throw new NotJson();
    }
    return Collections.unmodifiableList(items);
  }

  private String string() throws NotJson {
    pos++;
    StringBuilder b = new StringBuilder();
    while (pos < text.length()) {
      char c = text.charAt(pos++);
      if (c == '"') {
        return b.toString();
      }
      if (c < 0x20) {
        throw new NotJson();
      }
      if (c != '\\') {
        b.append(c);
        continue;
      }
      if (pos >= text.length()) {
        throw new NotJson();
      }
      char e = text.charAt(pos++);
      switch (e) {
        case '"', '\\', '/' -> b.append(e);
        case 'b' -> b.append('\b');
        case 'f' -> b.append('\f');
        case 'n' -> b.append('\n');
        case 'r' -> b.append('\r');
        case 't' -> b.append('\t');
        case 'u' -> {
          if (pos + 4 > text.length()) {
            throw new NotJson();
          }
          int code = 0;
          for (int i = 0; i < 4; i++) {
            int digit = Character.digit(text.charAt(pos++), 16);
            if (digit < 0) {
              throw new NotJson();
            }
            code = code * 16 + digit;
          }
          b.append((char) code);
        }
        default -> throw new NotJson();
      }
    }
    throw new NotJson();
  }

  private @Nullable Object word(String word, @Nullable Object value) throws NotJson {
    if (!text.startsWith(word, pos)) {
      throw new NotJson();
    }
    pos += word.length();
    return value;
  }

  /** RFC 8259's number: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)? */
  private BigDecimal number() throws NotJson {
    int start = pos;
    eat('-');
    if (eat('0')) {
      // no further integer digits after a leading zero
    } else if (!digits()) {
      throw new NotJson();
    }
    if (eat('.') && !digits()) {
      throw new NotJson();
    }
    if (eat('e') || eat('E')) {
      if (!eat('+')) {
        eat('-');
      }
      if (!digits()) {
        throw new NotJson();
      }
    }
    return new BigDecimal(text.substring(start, pos));
  }

  private boolean digits() {
    int start = pos;
    while (pos < text.length() && text.charAt(pos) >= '0' && text.charAt(pos) <= '9') {
      pos++;
    }
    return pos > start;
  }

  private boolean eat(char c) {
    if (pos < text.length() && text.charAt(pos) == c) {
      pos++;
      return true;
    }
    return false;
  }

  /** JSON's white space: space, tab, line feed, carriage return. */
  private void space() {
    while (pos < text.length() && " \t\n\r".indexOf(text.charAt(pos)) >= 0) {
      pos++;
    }
  }
}
