package org.armgals.testkit;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.Objects;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.ObjectConfig;
import org.jspecify.annotations.Nullable;

/**
 * An active object that a test hands out as an address and then asks what it received (Pekko's
 * {@code TestProbe}): objects send it data events like to any other; the test expects a message, a
 * given one or one of a type, or no message at all. Messages are kept in the order they arrived and
 * each expectation takes the oldest.
 *
 * <p>Two kinds, for the two clocks:
 *
 * <ul>
 *   <li>{@link #create(ActiveRuntime)}: an asynchronous object; expectations wait up to a {@link
 *       Duration} of real time.
 *   <li>{@link #create(ActiveRuntime, Stepper)}: a synchronous object on the stepper's manual
 *       clock; expectations step the stepper, at most a number of instants, and fail naming the
 *       instants. A message sent during instant {@code k} is taken at the release of {@code k + 1},
 *       like by any synchronous object: deterministic, whatever the threads.
 * </ul>
 *
 * <p>A failed expectation throws an {@link AssertionError} that names the probe, what was expected
 * and what came (or that nothing did). The probe answers no {@link org.armgals.active.Request}: one
 * sent to it fails like at any object that does not answer.
 *
 * <p>Threading: the test's thread expects; objects send from any thread.
 */
public final class Probe {

  /** A message and the instant it was taken at (0 on the real clock). */
  private record Received(Event event, long instant) {}

  private final ActiveObject<Receiver> object;
  private final @Nullable Stepper stepper;
  private final BlockingQueue<Received> received;

  private Probe(ActiveRuntime runtime, @Nullable Stepper stepper) {
    this.stepper = stepper;
    this.received = new LinkedBlockingQueue<>();
    Receiver receiver = new Receiver(received, stepper);
    this.object =
        stepper == null
            ? runtime.spawn(receiver)
            : runtime.spawn(receiver, ObjectConfig.synchronous(stepper.clock()));
  }

  /** An asynchronous probe in {@code runtime}, for tests on the real clock. */
  public static Probe create(ActiveRuntime runtime) {
    return new Probe(requireNonNull(runtime, "runtime"), null);
  }

  /**
   * A synchronous probe in {@code runtime} on {@code stepper}'s clock, for tests on a manual clock;
   * its expectations step {@code stepper}.
   */
  public static Probe create(ActiveRuntime runtime, Stepper stepper) {
    return new Probe(requireNonNull(runtime, "runtime"), requireNonNull(stepper, "stepper"));
  }

  /** Its address, to send it events or hand it to the objects under test. */
  public Address address() {
    return object.address();
  }

  /** A reference to it. */
  public ActiveRef<?> ref() {
    return object;
  }

  /**
   * Expects a message within {@code within} of real time.
   *
   * @return the oldest message received
   * @throws AssertionError none came within {@code within}
   * @throws IllegalStateException the probe is on a manual clock
   */
  public Event expectMessage(Duration within) {
    return awaitOne("a message", within).event();
  }

  /**
   * Expects {@code expected} (by {@code equals}) as the next message, within {@code within} of real
   * time.
   *
   * @throws AssertionError none came, or another one came first
   */
  public Event expectMessage(Event expected, Duration within) {
    requireNonNull(expected, "expected");
    return equalTo(expected, awaitOne(expected.toString(), within));
  }

  /**
   * Expects the next message to be a {@code type}, within {@code within} of real time.
   *
   * @throws AssertionError none came, or one of another type came first
   */
  public <T> T expectMessageType(Class<T> type, Duration within) {
    requireNonNull(type, "type");
    return ofType(type, awaitOne("a message of type " + type.getName(), within));
  }

  /**
   * Expects that no message comes for {@code during} of real time (and that none is waiting): the
   * probe waits all of it.
   *
   * @throws AssertionError a message came
   */
  public void expectNoMessage(Duration during) {
    requireNonNull(during, "during");
    requireRealTime(during.toString());
    Received first = received.poll();
    try {
      if (first == null) {
        first = received.poll(during.toNanos(), TimeUnit.NANOSECONDS);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new AssertionError(this + ": interrupted while expecting no message", e);
    }
    if (first != null) {
      throw new AssertionError(
          this + ": expected no message during " + show(during) + ", received " + first.event());
    }
  }

  /**
   * Expects a message within {@code instants} instants of the stepper, taking one that is already
   * waiting without stepping.
   *
   * @return the oldest message received
   * @throws AssertionError none came within {@code instants}
   * @throws IllegalArgumentException {@code instants} is less than 1
   * @throws IllegalStateException the probe is on the real clock
   */
  public Event expectMessage(long instants) {
    return stepForOne("a message", instants).event();
  }

  /**
   * Expects {@code expected} (by {@code equals}) as the next message within {@code instants}
   * instants.
   *
   * @throws AssertionError none came, or another one came first
   */
  public Event expectMessage(Event expected, long instants) {
    requireNonNull(expected, "expected");
    return equalTo(expected, stepForOne(expected.toString(), instants));
  }

  /**
   * Expects the next message to be a {@code type}, within {@code instants} instants.
   *
   * @throws AssertionError none came, or one of another type came first
   */
  public <T> T expectMessageType(Class<T> type, long instants) {
    requireNonNull(type, "type");
    return ofType(type, stepForOne("a message of type " + type.getName(), instants));
  }

  /**
   * Expects that no message comes during {@code instants} instants (and that none is waiting): the
   * probe steps all of them.
   *
   * @throws AssertionError a message came
   * @throws IllegalArgumentException {@code instants} is less than 1
   */
  public void expectNoMessage(long instants) {
    Stepper s = requireManual(instants);
    for (long i = 0; received.isEmpty() && i < instants; i++) {
      s.step();
    }
    Received first = received.poll();
    if (first != null) {
      throw new AssertionError(
          this
              + ": expected no message during "
              + instants
              + " instant(s), received "
              + first.event()
              + " at instant "
              + first.instant());
    }
  }

  @Override
  public String toString() {
    return "probe " + address();
  }

  private Received awaitOne(String what, Duration within) {
    requireNonNull(within, "within");
    requireRealTime(within.toString());
    Received r;
    try {
      r = received.poll(within.toNanos(), TimeUnit.NANOSECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new AssertionError(this + ": interrupted while expecting " + what, e);
    }
    if (r == null) {
      throw new AssertionError(
          this + ": expected " + what + " within " + show(within) + ", received nothing");
    }
    return r;
  }

  private Received stepForOne(String what, long instants) {
    Stepper s = requireManual(instants);
    long first = s.instant() + 1;
    for (long i = 0; received.isEmpty() && i < instants; i++) {
      s.step();
    }
    Received r = received.poll();
    if (r == null) {
      throw new AssertionError(
          this
              + ": expected "
              + what
              + " within "
              + instants
              + " instant(s) (instants "
              + first
              + " to "
              + s.instant()
              + "), received nothing");
    }
    return r;
  }

  private Event equalTo(Event expected, Received r) {
    if (!Objects.equals(expected, r.event())) {
      throw new AssertionError(this + ": expected " + expected + ", received " + r.event() + at(r));
    }
    return r.event();
  }

  private <T> T ofType(Class<T> type, Received r) {
    if (!type.isInstance(r.event())) {
      throw new AssertionError(
          this
              + ": expected a message of type "
              + type.getName()
              + ", received "
              + r.event()
              + " of type "
              + r.event().getClass().getName()
              + at(r));
    }
    return type.cast(r.event());
  }

  private String at(Received r) {
    return stepper == null ? "" : " at instant " + r.instant();
  }

  private void requireRealTime(String asked) {
    if (stepper != null) {
      throw new IllegalStateException(
          this
              + " is on a manual clock: expect within a number of instants, not a time ("
              + asked
              + ")");
    }
  }

  private Stepper requireManual(long instants) {
    if (stepper == null) {
      throw new IllegalStateException(
          this
              + " is on the real clock: expect within a time, not a number of instants ("
              + instants
              + "); create it with Probe.create(runtime, stepper) for a manual clock");
    }
    if (instants < 1) {
      throw new IllegalArgumentException("instants must be >= 1, was " + instants);
    }
    return stepper;
  }

  private static String show(Duration d) {
    return d.toMillis() + " ms";
  }

  /** The probe's servant: it keeps every data event it is given. */
  private static final class Receiver implements EventProcessor {
    private final BlockingQueue<Received> received;
    private final @Nullable Stepper stepper;

    Receiver(BlockingQueue<Received> received, @Nullable Stepper stepper) {
      this.received = received;
      this.stepper = stepper;
    }

    @Override
    public void process(Event event) {
      received.add(new Received(event, stepper == null ? 0 : stepper.instant()));
    }
  }
}
