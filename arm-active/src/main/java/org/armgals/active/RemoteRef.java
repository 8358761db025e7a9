package org.armgals.active;

import static java.util.Objects.requireNonNull;

import org.armgals.active.spi.Transport;
import org.jspecify.annotations.Nullable;

/**
 * A reference to an object of another runtime, through a {@link Transport}. Data events cross;
 * requests made of code (lambdas, method-request objects) need the servant's runtime and are
 * refused with a message that says so.
 */
final class RemoteRef<S> implements ActiveRef<S> {
  private final Address address;
  private final Transport transport;

  RemoteRef(Address address, Transport transport) {
    this.address = address;
    this.transport = transport;
  }

  @Override
  public Address address() {
    return address;
  }

  @Override
  public void send(Event event) {
    requireNonNull(event, "event");
    if (event instanceof Callable<?, ?>) {
      throw codeCannotCross("send(" + event.getClass().getSimpleName() + ")");
    }
    if (!address.equals(event.destination())) {
      throw new IllegalArgumentException(
          "event " + event + " is addressed to " + event.destination() + ", not " + address);
    }
    transport.send(address, event);
  }

  @Override
  public void send(ServantAction<? super S> action) {
    throw codeCannotCross("send(ServantAction)");
  }

  @Override
  public void sendWhen(Guard<? super S> guard, ServantAction<? super S> action) {
    throw codeCannotCross("sendWhen");
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> call(ServantFunction<? super S, R> function) {
    throw codeCannotCross("call(ServantFunction)");
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> callWhen(
      Guard<? super S> guard, ServantFunction<? super S, R> function) {
    throw codeCannotCross("callWhen");
  }

  @Override
  public Future signal(ServantAction<? super S> action) {
    throw codeCannotCross("signal");
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> call(
      SynchronizedMethodRequest<? super S, R> request) {
    throw codeCannotCross("call(SynchronizedMethodRequest)");
  }

  @Override
  public <I> I proxy(Class<I> type) {
    throw codeCannotCross("proxy");
  }

  private UnsupportedOperationException codeCannotCross(String what) {
    return new UnsupportedOperationException(
        what
            + " on "
            + address
            + ": that object lives in another runtime, and code cannot be sent there;"
            + " send it a data event with send(Event)");
  }

  @Override
  public boolean equals(@Nullable Object o) {
    return o instanceof RemoteRef<?> r && r.address.equals(address);
  }

  @Override
  public int hashCode() {
    return address.hashCode();
  }

  @Override
  public String toString() {
    return "RemoteRef[" + address + "]";
  }
}
