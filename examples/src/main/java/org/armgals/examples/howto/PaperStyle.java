package org.armgals.examples.howto;

import java.time.Duration;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.FutureValue;
import org.armgals.active.MethodRequest;
import org.armgals.active.SynchronizedMethodRequest;

/** Method requests as classes, with their guard, as in the paper (§4.1). */
final class PaperStyle {
  private PaperStyle() {}

  // tag::requests[]
  /** A one-way request (paper: MethodRequest). */
  static final class Deposit extends MethodRequest<Account> {
    private final long amount;

    Deposit(long amount) {
      this.amount = amount;
    }

    @Override
    protected void invoke(Account account) {
      account.deposit(amount);
    }
  }

  /** A guarded synchronized request (paper: SynchronizedMethodRequest). */
  static final class Withdraw extends SynchronizedMethodRequest<Account, Long> {
    private final long amount;

    Withdraw(long amount) {
      this.amount = amount;
    }

    @Override
    protected boolean guard(Account account) {
      return account.covers(amount); // isProcessable: false keeps the request queued
    }

    @Override
    protected Long invoke(Account account) {
      return account.withdraw(amount);
    }
  }

  // end::requests[]

  static long run() {
    try (ActiveRuntime runtime = ActiveRuntime.create()) {
      ActiveObject<Account> account = runtime.spawn(new Account());
      // tag::send-requests[]
      FutureValue<Long> left = account.call(new Withdraw(30)); // waits in the buffer: balance 0
      account.send(new Deposit(100)); // now the guard holds
      System.out.println("left: " + left.getValue(Duration.ofSeconds(5))); // 70
      // end::send-requests[]
      return left.getValue();
    }
  }
}
