package org.armgals.maam.sim;

/** The little JSON the trace needs: numbers written exactly, strings escaped. */
final class Json {

  private Json() {}

  static void string(StringBuilder out, String s) {
    out.append('"');
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      switch (c) {
        case '"' -> out.append("\\\"");
        case '\\' -> out.append("\\\\");
        case '\n' -> out.append("\\n");
        case '\r' -> out.append("\\r");
        case '\t' -> out.append("\\t");
        default -> {
          if (c < 0x20) {
            out.append(String.format("\\u%04x", (int) c));
          } else {
            out.append(c);
          }
        }
      }
    }
    out.append('"');
  }

  /** A double as Java prints it (shortest exact round trip); JSON has no NaN, so never NaN. */
  static void number(StringBuilder out, double d) {
    if (!Double.isFinite(d)) {
      throw new IllegalStateException("trace value " + d + " is not finite");
    }
    out.append(d);
  }
}
