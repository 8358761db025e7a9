package org.armgals.examples;

import static java.util.Objects.requireNonNull;

import java.io.PrintStream;
import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.FutureValue;
import org.armgals.active.RequestFailedException;
import org.armgals.active.WaitCycleException;
import org.jspecify.annotations.Nullable;

/**
 * Part 2 of the demo: asynchronous objects that ask each other through typed proxies and wait by
 * necessity. An order desk asks a catalog for a price and a stock for a reservation; both requests
 * run in parallel, and the desk waits only when it needs the values. A failure in a servant travels
 * back through the futures; two objects that wait for each other get a {@link WaitCycleException}
 * instead of a deadlock.
 */
final class FuturesDemo {
  private FuturesDemo() {}

  /** What part 2 observed. */
  record Result(String order, String failure, @Nullable WaitCycleException cycle) {}

  // Proxied interfaces must be public: the proxy calls the servant through reflection.

  public interface Catalog {
    FutureValue<Integer> price(String item);
  }

  public interface Stock {
    FutureValue<Boolean> reserve(String item, int quantity);
  }

  public interface Desk {
    FutureValue<String> order(String item, int quantity);
  }

  static final class CatalogServant implements Catalog {
    private final Map<String, Integer> prices = Map.of("widget", 12, "gadget", 30);

    @Override
    public FutureValue<Integer> price(String item) {
      Integer price = prices.get(item);
      if (price == null) {
        throw new IllegalArgumentException("no such item: " + item);
      }
      return FutureValue.completed(price);
    }
  }

  static final class StockServant implements Stock {
    private final Map<String, Integer> left = new HashMap<>(Map.of("widget", 5, "gadget", 1));

    @Override
    public FutureValue<Boolean> reserve(String item, int quantity) {
      int have = left.getOrDefault(item, 0);
      if (have < quantity) {
        return FutureValue.completed(false);
      }
      left.put(item, have - quantity);
      return FutureValue.completed(true);
    }
  }

  static final class DeskServant implements Desk {
    private final Catalog catalog;
    private final Stock stock;

    DeskServant(Catalog catalog, Stock stock) {
      this.catalog = requireNonNull(catalog, "catalog");
      this.stock = requireNonNull(stock, "stock");
    }

    @Override
    public FutureValue<String> order(String item, int quantity) {
      FutureValue<Integer> price = catalog.price(item); // both requests are now under way
      FutureValue<Boolean> reserved = stock.reserve(item, quantity);
      int unit = price.getValue(); // waits by necessity, here and on the next line
      String line = quantity + " x " + item;
      return FutureValue.completed(
          reserved.getValue() ? line + " = " + quantity * unit : line + ": out of stock");
    }
  }

  /** Two players that end up waiting for each other. */
  static final class Player {
    private @Nullable ActiveRef<Player> partner;

    void meet(ActiveRef<Player> partner) {
      this.partner = partner;
    }

    /** Asks the partner to answer, and waits. */
    String serve() {
      return partner().call(Player::answer).getValue();
    }

    /** Asks the partner (who is waiting for this answer) for the score, and waits: a cycle. */
    String answer() {
      return partner().call(Player::score).getValue();
    }

    String score() {
      return "15-love";
    }

    private ActiveRef<Player> partner() {
      return requireNonNull(partner, "partner");
    }
  }

  static Result run(ActiveRuntime runtime, PrintStream out, Duration timeout) {
    Catalog catalog = runtime.spawn(new CatalogServant()).proxy(Catalog.class);
    Stock stock = runtime.spawn(new StockServant()).proxy(Stock.class);
    Desk desk = runtime.spawn(new DeskServant(catalog, stock)).proxy(Desk.class);

    out.println("2. Asynchronous objects with futures: a desk asks a catalog and a stock at once");
    String order = desk.order("widget", 3).getValue(timeout);
    out.println("   order: " + order);

    String failure;
    try {
      desk.order("gizmo", 1).getValue(timeout);
      failure = "none";
    } catch (RequestFailedException e) {
      failure = rootCause(e).getMessage();
    }
    out.println(
        "   order of a gizmo failed in the catalog, and the desk's future says: " + failure);

    ActiveObject<Player> ping = runtime.spawn(new Player());
    ActiveObject<Player> pong = runtime.spawn(new Player());
    ping.send(p -> p.meet(pong));
    pong.send(p -> p.meet(ping));
    WaitCycleException cycle = null;
    try {
      ping.call(Player::serve).getValue(timeout);
    } catch (RequestFailedException e) {
      cycle = find(e, WaitCycleException.class);
    }
    out.println(
        "   ping waits for pong, which waits for ping: "
            + (cycle == null
                ? "no cycle reported"
                : "WaitCycleException on " + (cycle.cycle().size() - 1) + " objects, no deadlock"));
    return new Result(order, String.valueOf(failure), cycle);
  }

  private static Throwable rootCause(Throwable t) {
    Throwable c = t;
    while (c.getCause() != null) {
      c = c.getCause();
    }
    return c;
  }

  private static <T extends Throwable> @Nullable T find(Throwable t, Class<T> type) {
    for (Throwable c = t; c != null; c = c.getCause()) {
      if (type.isInstance(c)) {
        return type.cast(c);
      }
    }
    return null;
  }
}
