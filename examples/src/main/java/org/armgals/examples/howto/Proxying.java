package org.armgals.examples.howto;

import java.time.Duration;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Future;
import org.armgals.active.FutureValue;
import org.jspecify.annotations.Nullable;

/** A typed proxy over an active object. */
final class Proxying {
  private Proxying() {}

  // tag::teller[]
  /**
   * The proxied interface. It must be public (the proxy calls the servant by reflection) and each
   * method returns void (one-way request), Future (signal) or FutureValue (synchronized request).
   */
  public interface Teller {
    void deposit(long amount);

    Future audit();

    FutureValue<Long> balance();
  }

  /** The servant implements the interface and returns completed futures. */
  public static final class TellerServant implements Teller {
    private final Account account = new Account();
    private int audits;

    @Override
    public void deposit(long amount) {
      account.deposit(amount);
    }

    @Override
    public Future audit() {
      audits++;
      return FutureValue.<@Nullable Void>completed(null);
    }

    @Override
    public FutureValue<Long> balance() {
      return FutureValue.completed(account.balance());
    }
  }

  // end::teller[]

  static long run() {
    try (ActiveRuntime runtime = ActiveRuntime.create()) {
      // tag::proxy[]
      Teller teller = runtime.spawn(new TellerServant()).proxy(Teller.class);
      teller.deposit(70); // returns at once
      teller.audit().touch(); // waits until the audit ran
      long balance = teller.balance().getValue(Duration.ofSeconds(5)); // 70
      // end::proxy[]
      return balance;
    }
  }
}
