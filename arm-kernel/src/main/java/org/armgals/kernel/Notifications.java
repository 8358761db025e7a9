package org.armgals.kernel;

import java.util.Map;

/** What the notification records share. */
final class Notifications {
  private Notifications() {}

  static void checkSeq(long seq) {
    if (seq < 1) {
      throw new IllegalArgumentException("seq must be >= 1, was " + seq);
    }
  }

  static void common(Map<String, Object> p, Notification n) {
    p.put("kind", n.kind());
    p.put("entity", n.entity().toString());
    p.put("seq", n.seq());
  }
}
