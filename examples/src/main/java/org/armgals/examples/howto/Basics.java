package org.armgals.examples.howto;

import java.time.Duration;
import java.util.concurrent.CompletionStage;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Future;
import org.armgals.active.FutureValue;

/** Spawning an object, one-way and synchronized requests, guards. */
final class Basics {
  private Basics() {}

  /** What {@link #run} observed. */
  record Seen(long afterDeposits, long leftAfterGuarded, long fromStage) {}

  static Seen run() throws Exception {
    // tag::spawn[]
    ActiveRuntime runtime = ActiveRuntime.builder().name("bank").build();
    ActiveObject<Account> account = runtime.spawn(new Account()); // asynchronous, default buffer
    // end::spawn[]
    try {

      // tag::send-call[]
      account.send(a -> a.deposit(100)); // one-way: queued, returns at once
      FutureValue<Long> balance = account.call(Account::balance); // synchronized: a future
      long now = balance.getValue(Duration.ofSeconds(5)); // waits by necessity: 100

      Future done = account.signal(a -> a.deposit(20)); // synchronized, without a value
      done.touch(); // waits until the deposit has been made
      // end::send-call[]

      // tag::guards[]
      // Runs once the guard holds; until then it waits in the buffer and other requests pass it.
      FutureValue<Long> left = account.callWhen(a -> a.covers(500), a -> a.withdraw(500));
      account.sendWhen(a -> a.covers(1_000), a -> a.withdraw(1_000)); // one-way, guarded
      account.send(a -> a.deposit(400)); // 520 now: the first guard opens, the second does not
      System.out.println("left after withdrawing 500: " + left.getValue()); // 20
      // end::guards[]

      // tag::stage[]
      // For code outside the runtime that composes asynchronously instead of waiting:
      CompletionStage<Long> stage = account.call(Account::balance).toCompletionStage();
      long fromStage = stage.toCompletableFuture().get();
      // end::stage[]
      return new Seen(now, left.getValue(), fromStage);
    } finally {
      runtime.close();
    }
  }
}
