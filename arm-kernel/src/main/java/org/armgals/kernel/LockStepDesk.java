package org.armgals.kernel;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;

/**
 * The servant of a kernel's lock-step desk: an asynchronous object that receives the metas' answers
 * to the barriers of this kernel's lock-step entities ({@link Wire.Released}), from this runtime or
 * another, and hands them to the entities' {@link LockStepGate}s at once. A reactive entity takes
 * its events only at its releases; the desk lets the clock's stepping thread see an answer as soon
 * as it arrives.
 */
final class LockStepDesk implements EventProcessor {
  private final Map<Address, LockStepGate> gates = new ConcurrentHashMap<>();

  void register(Address entity, LockStepGate gate) {
    gates.put(entity, gate);
  }

  @Override
  public void process(Event event) {
    if (!(event instanceof Wire.Released r)) {
      throw new IllegalArgumentException(
          "the lock-step desk cannot process " + event + "; expected an answer to a barrier");
    }
    LockStepGate gate = gates.get(r.entity());
    if (gate != null) {
      gate.answered(r.instant(), r.requests());
    }
  }
}
