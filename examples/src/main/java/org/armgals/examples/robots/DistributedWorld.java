package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.TimeSource;
import org.armgals.gals.Emission;
import org.jspecify.annotations.Nullable;

/**
 * The world's mailbox, an asynchronous active object of the world's runtime: it takes what the
 * atoms' runtimes send ({@link DistributedWire.Joined}, {@link DistributedWire.Commands}) and keeps
 * the latest of each atom for the thread that runs the simulation, which waits on it.
 *
 * <p>Threading: {@link #process} runs on the runtime's workers, the waits on the simulation's
 * thread, {@link #ended} on whatever thread sees a child end; all synchronize on this object, so
 * what the worker stored happens-before what the waiting thread reads.
 */
final class DistributedWorld implements EventProcessor {
  private final TimeSource time;
  private final Map<Integer, DistributedWire.Joined> joined = new HashMap<>();
  private final Map<Integer, DistributedWire.Commands> commands = new HashMap<>();
  private final Set<Integer> ended = new HashSet<>();

  DistributedWorld(TimeSource time) {
    this.time = requireNonNull(time, "time");
  }

  @Override
  public synchronized void process(Event event) {
    if (!(event instanceof Emission emission)) {
      throw new IllegalArgumentException("expected an Emission, was " + event);
    }
    switch (emission.payload()) {
      case DistributedWire.Joined j -> joined.put(j.atom(), j);
      case DistributedWire.Commands c -> {
        DistributedWire.Commands last = commands.get(c.atom());
        if (last == null || c.cycle() > last.cycle()) {
          commands.put(c.atom(), c);
        }
      }
      default ->
          throw new IllegalArgumentException(
              "expected Joined or Commands, was " + emission.payload());
    }
    notifyAll();
  }

  /** Tells that atom {@code atom}'s process has ended: nobody waits for it any more. */
  synchronized void ended(int atom) {
    ended.add(atom);
    notifyAll();
  }

  synchronized boolean hasEnded(int atom) {
    return ended.contains(atom);
  }

  /**
   * Waits until atom {@code atom}'s runtime has joined; null if its process ended first or {@code
   * timeout} passed.
   */
  synchronized DistributedWire.@Nullable Joined awaitJoined(int atom, Duration timeout)
      throws InterruptedException {
    long deadline = time.nanoTime() + timeout.toNanos();
    for (long left = timeout.toNanos();
        !joined.containsKey(atom) && !ended.contains(atom) && left > 0;
        left = deadline - time.nanoTime()) {
      TimeUnit.NANOSECONDS.timedWait(this, left);
    }
    return joined.get(atom);
  }

  /**
   * Waits until atom {@code atom} has answered the readings of {@code cycle}, its process has
   * ended, or {@code timeout} has passed, and answers the latest commands it sent (null if none
   * yet).
   */
  synchronized DistributedWire.@Nullable Commands awaitCommands(
      int atom, long cycle, Duration timeout) throws InterruptedException {
    long deadline = time.nanoTime() + timeout.toNanos();
    for (long left = timeout.toNanos();
        !answered(atom, cycle) && !ended.contains(atom) && left > 0;
        left = deadline - time.nanoTime()) {
      TimeUnit.NANOSECONDS.timedWait(this, left);
    }
    return commands.get(atom);
  }

  /** The latest commands atom {@code atom} sent; null if none yet. */
  synchronized DistributedWire.@Nullable Commands latest(int atom) {
    return commands.get(atom);
  }

  private boolean answered(int atom, long cycle) {
    DistributedWire.Commands c = commands.get(atom);
    return c != null && c.cycle() >= cycle;
  }
}
