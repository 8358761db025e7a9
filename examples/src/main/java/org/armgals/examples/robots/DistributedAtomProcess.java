package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import java.util.List;
import org.armgals.examples.sim.BrokerLogin;
import org.armgals.examples.sim.ChildJvm;

/**
 * The JVM of one atom of {@link Distributed}: {@link DistributedAtomMain} in a {@link ChildJvm}
 * (this JVM's class path and Java, its output in a log file). It runs until its standard input
 * ends: {@link #close} closes it, and so does the end of this JVM, however it ends, so no atom
 * outlives the world.
 */
final class DistributedAtomProcess implements AutoCloseable {
  private final int atom;
  private final ChildJvm jvm;

  private DistributedAtomProcess(int atom, ChildJvm jvm) {
    this.atom = atom;
    this.jvm = jvm;
  }

  /**
   * Starts the JVM of atom {@code atom} with {@code args} for {@link DistributedAtomMain}, and the
   * broker's credentials, if any, in its environment (not on its command line).
   *
   * @throws IllegalStateException the process could not be started, naming the atom and why
   */
  static DistributedAtomProcess start(int atom, List<String> args, Path log, BrokerLogin login) {
    requireNonNull(login, "login");
    return new DistributedAtomProcess(
        atom,
        ChildJvm.start(
            "the JVM of atom " + atom,
            DistributedAtomMain.class,
            args,
            login.environment(),
            log,
            "128m",
            ChildJvm.Priority.SAME));
  }

  int atom() {
    return atom;
  }

  ProcessHandle handle() {
    return jvm.handle();
  }

  /** What the process said last, for an error message. */
  String tail() {
    return jvm.tail();
  }

  @Override
  public String toString() {
    return jvm.toString();
  }

  /** Closes its standard input: it leaves the broker and exits, without waiting for it. */
  void leave() {
    jvm.leave();
  }

  /**
   * Stops it: closes its standard input, so that it leaves the broker and exits, waits up to 10
   * seconds, then kills it. If interrupted, kills it at once and keeps the interrupt status.
   */
  @Override
  public void close() {
    jvm.close();
  }
}
