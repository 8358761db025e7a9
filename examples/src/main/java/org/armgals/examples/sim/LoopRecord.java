package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.LongSupplier;
import org.armgals.active.TimeSource;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.kernel.ReflectionEvent;
import org.armgals.kernel.spi.ReflectionListener;

/**
 * One JVM's side of the reflective loop's record, for a run whose robots and meta level live in
 * JVMs the example starts itself (as {@code distributed}'s atoms do): each JVM records what its
 * kernel tells ({@link #on}, the same records as {@link Reflection}'s), the robots' JVMs write
 * theirs into a file ({@link #write}), and the run merges every side into {@value Reflection#LOOP}
 * and the summary's lines of the loop ({@link #finish}), as a run with {@code --meta remote} does.
 *
 * <p>Threading: {@link #on} on the kernel's threads, the rest on any thread.
 */
public final class LoopRecord implements ReflectionListener {
  private final LoopRecorder recorder;

  /**
   * @param periodNanos the control period: the meta's records fall in the cycle of the base level's
   *     time they were decided on
   * @param cycle the cycle of the world the robots' records of this JVM fall in, when they are made
   */
  public LoopRecord(long periodNanos, LongSupplier cycle) {
    this.recorder =
        new LoopRecorder(periodNanos, requireNonNull(cycle, "cycle"), TimeSource.system());
  }

  /** Records the loop of the robot named {@code robot}; others' are ignored. Answers this. */
  public LoopRecord watch(String robot) {
    recorder.watch(robot);
    return this;
  }

  /** Records the meta side of the meta-entity named {@code meta}. Answers this. */
  public LoopRecord watchMeta(String meta) {
    recorder.watchMeta(meta);
    return this;
  }

  @Override
  public void on(ReflectionEvent event) {
    recorder.on(event);
  }

  /** Writes what it recorded so far into {@code file}, one JSON object per line. */
  public void write(Path file) {
    MetaMain.writeLoop(requireNonNull(file, "file"), recorder.lines());
  }

  /**
   * Merges {@code here}'s records and those written into {@code files} (a file missing is a side
   * that recorded nothing: a JVM killed, say; each file read is deleted) into {@value
   * Reflection#LOOP} in {@code dir} (within a cycle, the robots' side first, then each meta's
   * records robot by robot), and answers the summary's lines of the loop: a meta level running
   * where {@code place} says, in lock step unless {@code settings} says real time.
   */
  public static List<Summary.Entry> finish(
      Path dir, LoopRecord here, List<Path> files, RunSettings settings, String place) {
    requireNonNull(place, "place");
    requireNonNull(dir, "dir");
    requireNonNull(settings, "settings");
    List<LoopRecorder.Line> lines = new ArrayList<>();
    // One meta hears robots of several JVMs, in the order their notifications happen to come:
    // its records are placed robot by robot, each robot's in the order the meta made them.
    for (LoopRecorder.Line l : here.recorder.lines()) {
      lines.add(
          l.side() == LoopRecorder.META
              ? new LoopRecorder.Line(
                  l.cycle(),
                  l.side(),
                  l.group() + "/" + l.fields().get("robot"),
                  l.order(),
                  l.fields())
              : l);
    }
    for (Path file : files) {
      lines.addAll(MetaMain.readLoop(file));
      try {
        Files.deleteIfExists(file);
      } catch (IOException e) {
        throw new UncheckedIOException("cannot delete " + file, e);
      }
    }
    List<Map<String, Object>> loop = LoopRecorder.merge(lines);
    Reflection.write(dir.resolve(Reflection.LOOP), loop);
    return LoopSummary.of(loop, true, settings, place, here.recorder.overruns(), List.of())
        .entries();
  }
}
