package org.armgals.active.jms;

import java.util.HashMap;
import java.util.Map;

/**
 * The receiving side of a transport's routes: per route (the sending transport, the topic and the
 * guarantee), the highest sequence number taken. A message whose first number is beyond the next
 * one expected shows a gap: the messages in between are lost. A message whose numbers were all
 * taken already is a duplicate (an at-least-once message delivered again); one that overlaps the
 * numbers taken keeps only its new events. Sequence numbers of a route start at 1, so a route whose
 * first messages never arrived counts them lost too.
 *
 * <p>Thread-safe; each consumer has its own ledger, so it is not contended.
 */
final class RouteLedger {

  /**
   * What to do with a message.
   *
   * @param skip how many of its events, from the first, were taken already
   * @param lost how many messages before it never arrived
   */
  record Verdict(int skip, long lost) {
    static final Verdict TAKE = new Verdict(0, 0);
  }

  private final Map<String, long[]> last = new HashMap<>();

  /**
   * Takes the message of {@code route} whose {@code count} events are numbered from {@code first}.
   *
   * @throws IllegalArgumentException {@code first} < 1 or {@code count} < 1
   */
  synchronized Verdict take(String route, long first, int count) {
    if (first < 1 || count < 1) {
      throw new IllegalArgumentException(
          "route sequence numbers start at 1 and a message holds at least one event; was first "
              + first
              + ", count "
              + count);
    }
    long[] taken = last.computeIfAbsent(route, r -> new long[1]);
    long end = first + count - 1;
    if (end <= taken[0]) {
      return new Verdict(count, 0);
    }
    long lost = Math.max(0, first - taken[0] - 1);
    int skip = (int) Math.max(0, taken[0] - first + 1);
    taken[0] = end;
    return lost == 0 && skip == 0 ? Verdict.TAKE : new Verdict(skip, lost);
  }

  /** The highest number taken on {@code route}, 0 if none. */
  synchronized long last(String route) {
    long[] taken = last.get(route);
    return taken == null ? 0 : taken[0];
  }
}
