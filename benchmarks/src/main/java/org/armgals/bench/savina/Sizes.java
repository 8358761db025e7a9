package org.armgals.bench.savina;

/**
 * The sizes of the workloads, the same for every implementation. Each default is chosen so that a
 * run takes one to five seconds on a two-core machine for armgals and Pekko where their speeds
 * allow it; where they differ too much (creation, futurertt) the faster one runs shorter. {@code
 * -Dsavina.<key>=<n>} overrides one (give every implementation the same value when comparing).
 *
 * @param pingpongMessages one-way messages bounced between the two players (even)
 * @param countingIncrements increments sent to the counter
 * @param ringObjects objects in the thread ring
 * @param ringLaps times the token goes round the ring
 * @param fjObjects objects that receive events from the one sender
 * @param fjEventsPerObject events each of them receives
 * @param creationObjects objects created by one creation run
 * @param futureRequests sequential synchronized requests of one futurertt run
 * @param memObjects idle objects made by the memory probe
 */
public record Sizes(
    int pingpongMessages,
    int countingIncrements,
    int ringObjects,
    int ringLaps,
    int fjObjects,
    int fjEventsPerObject,
    int creationObjects,
    int futureRequests,
    int memObjects) {

  /** Checks every size. */
  public Sizes {
    positive("pingpong.messages", pingpongMessages);
    if (pingpongMessages % 2 != 0) {
      throw new IllegalArgumentException(
          "pingpong.messages must be even (each player gets half), was " + pingpongMessages);
    }
    positive("counting.increments", countingIncrements);
    positive("threadring.objects", ringObjects);
    positive("threadring.laps", ringLaps);
    positive("fjthrput.objects", fjObjects);
    positive("fjthrput.events", fjEventsPerObject);
    positive("creation.objects", creationObjects);
    positive("futurertt.requests", futureRequests);
    positive("mem.objects", memObjects);
  }

  /** The defaults, each overridden by its system property {@code savina.<key>} if set. */
  public static Sizes fromSystemProperties() {
    return new Sizes(
        property("pingpong.messages", 5_000_000),
        property("counting.increments", 20_000_000),
        property("threadring.objects", 1_000),
        property("threadring.laps", 10_000),
        property("fjthrput.objects", 1_000),
        property("fjthrput.events", 20_000),
        property("creation.objects", 100_000),
        property("futurertt.requests", 100_000),
        property("mem.objects", 1_000_000));
  }

  /** Hops of the thread ring's token: its operations. */
  public long ringHops() {
    return (long) ringObjects * ringLaps;
  }

  /** Events of fjthrput: its operations. */
  public long fjEvents() {
    return (long) fjObjects * fjEventsPerObject;
  }

  private static int property(String key, int fallback) {
    String text = System.getProperty("savina." + key);
    if (text == null) {
      return fallback;
    }
    try {
      return Integer.parseInt(text.replace("_", ""));
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(
          "system property savina." + key + " must be an integer, was '" + text + "'", e);
    }
  }

  private static void positive(String key, int value) {
    if (value < 1) {
      throw new IllegalArgumentException("savina." + key + " must be >= 1, was " + value);
    }
  }
}
