package org.armgals.examples.robots;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.function.LongSupplier;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.sim.Journal;

/** What the walker's and the caterpillar's tests share: settings and a journal that remembers. */
final class GaitsTestSupport {

  private GaitsTestSupport() {}

  /** Default settings, 10 ms cycles, with {@code atoms} if given, writing to {@code out}. */
  static RunSettings settings(Optional<Integer> atoms, OptionalLong cycles, Path out) {
    return new RunSettings(
        cycles, Optional.empty(), Duration.ofMillis(10), 1, atoms, false, Optional.empty(), out);
  }

  static RunSettings settings(Optional<Integer> atoms) {
    return settings(atoms, OptionalLong.empty(), Path.of("unused"));
  }

  /** A journal that keeps what it is told, with the simulated time it was told at. */
  static final class TestJournal implements Journal {
    private final LongSupplier nanos;
    final List<String> adaptations = new ArrayList<>();
    final List<String> notes = new ArrayList<>();

    /** A journal telling the time from {@code nanos}: {@code sim::timeNanos}, say. */
    TestJournal(LongSupplier nanos) {
      this.nanos = nanos;
    }

    @Override
    public void adaptation(int atom, String what, String why) {
      adaptations.add(
          nanos.getAsLong() / 1e9 + " s atom " + atom + ": " + what + " because " + why);
    }

    @Override
    public void note(int atom, String text) {
      notes.add(nanos.getAsLong() / 1e9 + " s atom " + atom + ": " + text);
    }
  }
}
