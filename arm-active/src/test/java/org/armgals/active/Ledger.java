package org.armgals.active;

import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * What the stress tests check about a run: each event sent ends in exactly one of processed,
 * dropped or rejected, and the processed events of each sender come in the order it sent them.
 *
 * <p>Plain Java, no AssertJ: it also runs inside Lincheck's model checker, which calls {@code
 * equals} on objects that AssertJ's assertions refuse it to.
 */
final class Ledger {
  private Ledger() {}

  private record Id(int thread, int seq) {}

  /**
   * Checks that every event {@code 1 .. sent[t]} of every thread {@code t} is in exactly one of
   * {@code processed}, {@code dropped} and {@code rejected}, that these hold nothing else, and that
   * each thread's processed events are in the order it sent them.
   *
   * @throws AssertionError naming the event and its fates
   */
  static void assertEachSentEventAccountedForOnce(
      int[] sent, List<Tagged> processed, Collection<Tagged> dropped, Collection<Tagged> rejected) {
    Map<Id, String> fate = new HashMap<>();
    record(fate, processed, "processed");
    record(fate, dropped, "dropped");
    record(fate, rejected, "rejected");
    Set<Id> expected = new HashSet<>();
    for (int thread = 0; thread < sent.length; thread++) {
      for (int seq = 1; seq <= sent[thread]; seq++) {
        expected.add(new Id(thread, seq));
      }
    }
    if (!fate.keySet().equals(expected)) {
      Set<Id> lost = new HashSet<>(expected);
      lost.removeAll(fate.keySet());
      Set<Id> unknown = new HashSet<>(fate.keySet());
      unknown.removeAll(expected);
      throw new AssertionError(
          "events sent but neither processed, dropped nor rejected: "
              + lost
              + "; events never sent: "
              + unknown
              + " (processed "
              + processed
              + ", dropped "
              + dropped
              + ", rejected "
              + rejected
              + ")");
    }
    assertInSenderOrder(processed);
  }

  /**
   * Checks that the events of each thread come in increasing {@code seq}.
   *
   * @throws AssertionError naming the thread and the processing order
   */
  static void assertInSenderOrder(List<Tagged> processed) {
    Map<Integer, Integer> last = new HashMap<>();
    for (Tagged t : processed) {
      Integer before = last.put(t.thread(), t.seq());
      if (before != null && t.seq() <= before) {
        throw new AssertionError(
            "thread " + t.thread() + "'s events processed out of order: " + processed);
      }
    }
  }

  private static void record(Map<Id, String> fate, Collection<Tagged> events, String what) {
    for (Tagged t : events) {
      String earlier = fate.put(new Id(t.thread(), t.seq()), what);
      if (earlier != null) {
        throw new AssertionError("event " + t + " is " + what + " but was already " + earlier);
      }
    }
  }
}
