package org.armgals.examples.howto;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.FutureValue;
import org.armgals.active.ObjectStoppedException;
import org.armgals.active.RequestFailedException;
import org.armgals.active.ShutdownMode;

/** Failures, the error handler, stopping an object and shutting down. */
final class Errors {
  private Errors() {}

  /** What {@link #run} observed. */
  record Seen(
      String cause, long balanceAfter, List<String> handled, boolean refused, boolean clean) {}

  static Seen run() {
    // tag::errors[]
    List<String> handled = new CopyOnWriteArrayList<>();
    ActiveRuntime runtime =
        ActiveRuntime.builder()
            .errorHandler((object, event, error) -> handled.add(object + ": " + error.getMessage()))
            .build();
    ActiveObject<Account> account = runtime.spawn(new Account());

    FutureValue<Long> bad =
        account.call(
            a -> {
              a.deposit(-5); // throws IllegalArgumentException
              return a.balance();
            });
    String cause;
    try {
      bad.getValue();
      cause = "none";
    } catch (RequestFailedException e) { // the servant's exception is the cause
      cause = e.getCause().getMessage(); // amount must be > 0, was -5
    }
    long balance = account.call(Account::balance).getValue(); // the object goes on
    // end::errors[]

    // tag::stop[]
    account.stop(); // queued requests are discarded, their futures fail
    boolean refused = false;
    try {
      account.send(a -> a.deposit(1));
    } catch (ObjectStoppedException e) { // names the stopped object
      refused = true;
    }
    // end::stop[]

    // tag::shutdown[]
    // DRAIN: objects finish what is queued (and what they send each other meanwhile), then stop.
    // CANCEL: stop now; queued requests fail, threads waiting by necessity are interrupted.
    boolean clean = runtime.shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(5));
    // end::shutdown[]
    return new Seen(cause, balance, handled, refused, clean);
  }
}
