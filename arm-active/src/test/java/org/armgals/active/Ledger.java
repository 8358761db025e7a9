package org.armgals.active;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/**
 * What the stress tests check about a run: each event sent ends in exactly one of processed,
 * dropped or rejected, and the processed events of each sender come in the order it sent them.
 *
 * <p>Plain Java over arrays, no AssertJ and no hashing: it also runs inside Lincheck's model
 * checker, which follows every call it makes (and calls {@code equals} on objects that AssertJ's
 * assertions refuse it to).
 */
final class Ledger {
  private Ledger() {}

  /**
   * Checks that every event {@code 1 .. sent[t]} of every thread {@code t} is in exactly one of
   * {@code processed}, {@code dropped} and {@code rejected}, that these hold nothing else, and that
   * each thread's processed events are in the order it sent them.
   *
   * @throws AssertionError naming the event and its fates
   */
  static void assertEachSentEventAccountedForOnce(
      int[] sent, List<Tagged> processed, Collection<Tagged> dropped, Collection<Tagged> rejected) {
    String[][] fate = new String[sent.length][];
    for (int thread = 0; thread < sent.length; thread++) {
      fate[thread] = new String[sent[thread] + 1];
    }
    record(fate, processed, "processed");
    record(fate, dropped, "dropped");
    record(fate, rejected, "rejected");
    List<String> lost = new ArrayList<>();
    for (int thread = 0; thread < sent.length; thread++) {
      for (int seq = 1; seq <= sent[thread]; seq++) {
        if (fate[thread][seq] == null) {
          lost.add(thread + "/" + seq);
        }
      }
    }
    if (!lost.isEmpty()) {
      throw new AssertionError(
          "events (thread/seq) sent but neither processed, dropped nor rejected: "
              + lost
              + " (processed "
              + processed
              + ", dropped "
              + dropped
              + ", rejected "
              + rejected
              + ")");
    }
    assertInSenderOrder(sent.length, processed);
  }

  /**
   * Checks that the events of each of {@code threads} threads come in increasing {@code seq}.
   *
   * @throws AssertionError naming the thread and the processing order
   */
  static void assertInSenderOrder(int threads, List<Tagged> processed) {
    int[] last = new int[threads];
    for (Tagged t : processed) {
      if (t.seq() <= last[t.thread()]) {
        throw new AssertionError(
            "thread " + t.thread() + "'s events processed out of order: " + processed);
      }
      last[t.thread()] = t.seq();
    }
  }

  private static void record(String[][] fate, Collection<Tagged> events, String what) {
    for (Tagged t : events) {
      if (t.thread() >= fate.length || t.seq() < 1 || t.seq() >= fate[t.thread()].length) {
        throw new AssertionError("event " + t + " is " + what + " but was never sent");
      }
      String earlier = fate[t.thread()][t.seq()];
      if (earlier != null) {
        throw new AssertionError("event " + t + " is " + what + " but was already " + earlier);
      }
      fate[t.thread()][t.seq()] = what;
    }
  }
}
