package org.armgals.active;

import java.util.Map;

/** {@link Filter#ALL}: no selector. */
enum AcceptAll implements Filter {
  INSTANCE;

  @Override
  public String expression() {
    return "";
  }

  @Override
  public boolean matches(Map<String, ?> properties) {
    SelectorFilter.checkValues(properties);
    return true;
  }

  @Override
  public String toString() {
    return "Filter.ALL";
  }
}
