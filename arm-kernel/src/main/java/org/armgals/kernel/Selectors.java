package org.armgals.kernel;

import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.active.Filter;

/**
 * The filters of behavioral metas: arm-active's {@link Filter} (JMS message selectors evaluated by
 * Artemis's own selector implementation) over a notification's properties, keeping only the values
 * a JMS message property can hold (a list-valued observation is invisible to selectors).
 */
final class Selectors {
  private Selectors() {}

  static boolean matches(Filter filter, Notification n) {
    if (filter == Filter.ALL) {
      return true;
    }
    Map<String, Object> p = new LinkedHashMap<>();
    for (var e : n.properties().entrySet()) {
      Object v = e.getValue();
      if (v instanceof String
          || v instanceof Boolean
          || v instanceof Byte
          || v instanceof Short
          || v instanceof Integer
          || v instanceof Long
          || v instanceof Float
          || v instanceof Double) {
        p.put(e.getKey(), v);
      }
    }
    return filter.matches(p);
  }
}
