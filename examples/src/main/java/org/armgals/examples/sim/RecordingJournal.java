package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import org.armgals.maam.sim.Simulation;

/** The journal of a run: notes go into the trace, adaptations also into the recording. */
final class RecordingJournal implements Journal {
  private final Simulation sim;
  private final Recording recording;

  RecordingJournal(Simulation sim, Recording recording) {
    this.sim = sim;
    this.recording = recording;
  }

  @Override
  public void adaptation(int atom, String what, String why) {
    requireNonNull(what, "what");
    requireNonNull(why, "why");
    recording.adaptation(new Recording.Adaptation(sim.timeNanos() / 1e9, atom, what, why));
    sim.note(atom, "adaptation: " + what + ", because " + why);
  }

  @Override
  public void note(int atom, String text) {
    sim.note(atom, requireNonNull(text, "text"));
  }
}
