package org.armgals.active;

/** Failure plumbing shared by the runtime's loops. */
final class ActiveRuntimeErrors {
  private ActiveRuntimeErrors() {}

  /** Rethrows what no loop should swallow: the JVM is in trouble (Reactor's throwIfFatal). */
  static void throwIfFatal(Throwable t) {
    if (t instanceof VirtualMachineError e) {
      throw e;
    }
    if (t instanceof LinkageError e) {
      throw e;
    }
  }
}
