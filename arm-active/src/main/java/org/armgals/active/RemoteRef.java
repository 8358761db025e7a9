package org.armgals.active;

import static java.util.Objects.requireNonNull;

import org.armgals.active.spi.Transport;
import org.jspecify.annotations.Nullable;

/**
 * A reference whose data events and requests go through a {@link Transport}: to an object of
 * another runtime, or, when the transport {@linkplain Transport#routesLocalEvents() routes local
 * events too} ("JMS everywhere"), to one of this runtime. Code (lambdas, method-request objects)
 * needs the servant's runtime: it goes to the local object directly when there is one, and is
 * refused with a message that says so otherwise.
 */
final class RemoteRef<S> implements ActiveRef<S> {
  private final Address address;
  private final Transport transport;
  private final @Nullable Core<S> local;

  RemoteRef(Address address, Transport transport, @Nullable Core<S> local) {
    this.address = address;
    this.transport = transport;
    this.local = local;
  }

  @Override
  public Address address() {
    return address;
  }

  @Override
  public void send(Event event) {
    requireNonNull(event, "event");
    if (event instanceof Callable<?, ?>) {
      code("send(" + event.getClass().getSimpleName() + ")").send(event);
      return;
    }
    if (!address.equals(event.destination())) {
      throw new IllegalArgumentException(
          "event " + event + " is addressed to " + event.destination() + ", not " + address);
    }
    transport.send(address, event);
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> ask(Request<R> request) {
    requireNonNull(request, "request");
    if (!address.equals(request.destination())) {
      throw new IllegalArgumentException(
          "request " + request + " is addressed to " + request.destination() + ", not " + address);
    }
    return transport.ask(address, request);
  }

  @Override
  public void send(ServantAction<? super S> action) {
    code("send(ServantAction)").send(action);
  }

  @Override
  public void sendWhen(Guard<? super S> guard, ServantAction<? super S> action) {
    code("sendWhen").sendWhen(guard, action);
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> call(ServantFunction<? super S, R> function) {
    return code("call(ServantFunction)").call(function);
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> callWhen(
      Guard<? super S> guard, ServantFunction<? super S, R> function) {
    return code("callWhen").callWhen(guard, function);
  }

  @Override
  public Future signal(ServantAction<? super S> action) {
    return code("signal").signal(action);
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> call(
      SynchronizedMethodRequest<? super S, R> request) {
    return code("call(SynchronizedMethodRequest)").call(request);
  }

  @Override
  public <I> I proxy(Class<I> type) {
    return code("proxy").proxy(type);
  }

  /** The local object that runs code, or a refusal naming {@code what}. */
  private ActiveRef<S> code(String what) {
    Core<S> l = local;
    if (l != null) {
      return l;
    }
    throw new UnsupportedOperationException(
        what
            + " on "
            + address
            + ": that object lives in another runtime, and code cannot be sent there;"
            + " send it a data event with send(Event) or a Request with ask(Request)");
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
