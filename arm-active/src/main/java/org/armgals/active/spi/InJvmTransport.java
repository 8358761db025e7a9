package org.armgals.active.spi;

import static java.util.Objects.requireNonNull;

import java.util.concurrent.ConcurrentHashMap;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.FutureValue;
import org.armgals.active.Request;
import org.jspecify.annotations.Nullable;

/** Links the runtimes of one JVM: a map from runtime name to its inbound side. */
final class InJvmTransport implements Transport {
  private final ConcurrentHashMap<String, Inbound> runtimes = new ConcurrentHashMap<>();

  @Override
  public void attach(String runtime, Inbound inbound) {
    requireNonNull(runtime, "runtime");
    requireNonNull(inbound, "inbound");
    if (runtimes.putIfAbsent(runtime, inbound) != null) {
      throw new IllegalStateException("a runtime named '" + runtime + "' is already attached");
    }
  }

  @Override
  public void detach(String runtime) {
    runtimes.remove(requireNonNull(runtime, "runtime"));
  }

  @Override
  public void send(Address destination, Event event) {
    requireNonNull(destination, "destination");
    requireNonNull(event, "event");
    inbound(destination).deliver(destination, event);
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> ask(Address destination, Request<R> request) {
    requireNonNull(destination, "destination");
    requireNonNull(request, "request");
    return inbound(destination).ask(destination, request);
  }

  private Inbound inbound(Address destination) {
    Inbound inbound = runtimes.get(destination.runtime());
    if (inbound == null) {
      throw new IllegalArgumentException(
          "no runtime named '"
              + destination.runtime()
              + "' is attached to this transport; attached: "
              + runtimes.keySet());
    }
    return inbound;
  }

  @Override
  public String toString() {
    return "InJvmTransport" + runtimes.keySet();
  }
}
