package org.armgals.bench;

/** The option parsing the benchmark entry points share: a value after its option, a count. */
public final class Args {
  private Args() {}

  /**
   * The value at {@code args[i]}, the one after {@code option}.
   *
   * @throws IllegalArgumentException if there is none, naming the option
   */
  public static String value(String[] args, int i, String option) {
    if (i >= args.length) {
      throw new IllegalArgumentException(option + " needs a value");
    }
    return args[i];
  }

  /**
   * {@code text} as an integer of at least {@code min}.
   *
   * @throws IllegalArgumentException if it is not one, naming the option, the bound and the text
   */
  public static int count(String text, String option, int min) {
    String expected = option + " must be an integer >= " + min + ", was '" + text + "'";
    int n;
    try {
      n = Integer.parseInt(text);
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(expected, e);
    }
    if (n < min) {
      throw new IllegalArgumentException(expected);
    }
    return n;
  }
}
