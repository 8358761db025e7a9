package org.armgals.maam.sim;

import java.util.PriorityQueue;
import java.util.SplittableRandom;

/**
 * Neighbour messages in flight: each is delayed by the simulation's message delay and lost with its
 * packet-loss probability, drawn from the simulation's seeded generator in send order.
 */
final class MessageBus {

  private record InFlight(long dueNanos, long seq, AtomModel to, ReceivedMessage message) {}

  private final PriorityQueue<InFlight> queue =
      new PriorityQueue<>(
          (x, y) ->
              x.dueNanos != y.dueNanos
                  ? Long.compare(x.dueNanos, y.dueNanos)
                  : Long.compare(x.seq, y.seq));
  private final SplittableRandom random;
  private final long delayNanos;
  private double loss;
  private long seq;

  MessageBus(long seed, long delayNanos, double loss) {
    this.random = new SplittableRandom(seed);
    this.delayNanos = delayNanos;
    this.loss = loss;
  }

  void setLoss(double loss) {
    SimulationBuilder.checkProbability(loss);
    this.loss = loss;
  }

  /** Queues a message to {@code to}; returns false if the draw lost it. */
  boolean send(long nowNanos, AtomModel to, ReceivedMessage message) {
    if (loss > 0 && random.nextDouble() < loss) {
      return false;
    }
    queue.add(new InFlight(nowNanos + delayNanos, seq++, to, message));
    return true;
  }

  /** Hands every message due by {@code nowNanos} to its atom's inbox; failed atoms drop theirs. */
  void deliver(long nowNanos) {
    while (!queue.isEmpty() && queue.peek().dueNanos <= nowNanos) {
      InFlight m = queue.poll();
      if (!m.to.failed) {
        m.to.inbox.add(m.message);
      }
    }
  }
}
