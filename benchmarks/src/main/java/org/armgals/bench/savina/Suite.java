package org.armgals.bench.savina;

/**
 * The workloads of one implementation, sharing one runtime (an armgals runtime, a Pekko actor
 * system or the yardstick's pool) for the life of the JVM. Not thread-safe: the harness uses it
 * from its main thread.
 */
public interface Suite extends AutoCloseable {

  /** The implementation's name as printed: {@code armgals}, {@code pekko} or {@code yardstick}. */
  String impl();

  /**
   * The workload called {@code name}.
   *
   * @throws IllegalArgumentException an unknown name (the message lists the known ones)
   */
  Workload workload(String name);

  /** How this implementation makes idle objects, for the memory probe. */
  IdleObjects idleObjects();

  /** Shuts the runtime down. */
  @Override
  void close();
}
