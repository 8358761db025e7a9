package org.armgals.examples.sim;

/**
 * Watches a run as it goes, for the live view: what {@code armgals run --live} serves to a browser.
 * Each event is one JSON object, made by the run ({@link LiveJson} says what each holds).
 *
 * <p>Threading: {@link #started}, {@link #frame} and {@link #ended} on the thread that runs the
 * simulation, in that order; {@link #loop} on any thread (the kernel's, for the records of the
 * meta's side). Implementations return at once: the run waits for none of them.
 */
public interface RunWatcher {

  /** A watcher that looks at nothing: a run without a live view. */
  RunWatcher NONE =
      new RunWatcher() {
        @Override
        public void started(String start) {}

        @Override
        public void frame(long cycle, String frame) {}

        @Override
        public void loop(String record) {}

        @Override
        public void ended(String end) {}
      };

  /** Before the first cycle: the example, its scene and the run's length. */
  void started(String start);

  /**
   * After cycle {@code cycle}: the molecule, the energy, the robots' programs, the metas' models.
   */
  void frame(long cycle, String frame);

  /** One record of the reflective loop, as {@code loop.jsonl} has it, with the cycle it is of. */
  void loop(String record);

  /** When the run has ended: how many cycles it ran of how many. */
  void ended(String end);
}
