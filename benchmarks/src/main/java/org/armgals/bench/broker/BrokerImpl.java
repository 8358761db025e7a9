package org.armgals.bench.broker;

/**
 * One implementation of the broker benchmark's workloads over a given broker and transport. Each
 * call sets up its clients, measures, and tears them down, so that runs do not share state.
 */
interface BrokerImpl {
  /** {@code raw} or {@code armgals}, as printed. */
  String name();

  /**
   * Sends {@code messages} one-way events of {@link BrokerBench#PAYLOAD_BYTES} bytes from one
   * sender to one receiver and returns the events per second, from the first send until the last
   * event is received.
   */
  double events(BenchBroker broker, Transport transport, Guarantee guarantee, int messages)
      throws Exception;

  /**
   * Makes {@code requests} synchronized requests one after another, waiting for each reply, and
   * returns their round-trip times in nanoseconds.
   */
  long[] futureRoundTrips(
      BenchBroker broker, Transport transport, Guarantee guarantee, int requests) throws Exception;
}
