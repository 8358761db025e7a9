package org.armgals.examples.howto;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.BufferFullException;
import org.armgals.active.Event;
import org.armgals.active.ObjectConfig;
import org.armgals.active.OverflowPolicy;
import org.armgals.active.spi.ObjectListener;

/** Bounded buffers: capacity, overflow policies, hearing about drops. */
final class Overflow {
  private Overflow() {}

  /** What {@link #run} observed. */
  record Seen(boolean rejected, long dropped, OverflowPolicy parsed) {}

  static Seen run() throws InterruptedException {
    try (ActiveRuntime runtime = ActiveRuntime.create()) {
      // tag::policies[]
      ObjectConfig strict =
          ObjectConfig.asynchronous()
              .withCapacity(2)
              .withOverflow(OverflowPolicy.reject()); // or block(timeout), dropNewest, dropOldest

      AtomicLong dropped = new AtomicLong();
      ObjectListener countDrops =
          new ObjectListener() {
            @Override
            public void onDropped(Address object, Event event, OverflowPolicy policy) {
              dropped.incrementAndGet(); // on the sender's thread: quick, thread-safe
            }
          };
      ObjectConfig latestWins =
          ObjectConfig.asynchronous()
              .withCapacity(2)
              .withOverflow(OverflowPolicy.dropOldest())
              .withListener(countDrops);

      OverflowPolicy fromText = OverflowPolicy.parse("block:PT2S"); // from configuration
      // end::policies[]

      // tag::reject[]
      CountDownLatch busy = new CountDownLatch(1);
      CountDownLatch release = new CountDownLatch(1);
      ActiveObject<Account> account = runtime.spawn(new Account(), strict);
      account.send(
          a -> { // keeps the object busy, so what follows stays queued
            busy.countDown();
            release.await();
          });
      busy.await();
      account.send(a -> a.deposit(1));
      account.send(a -> a.deposit(2)); // two queued: the buffer is full
      boolean rejected = false;
      try {
        account.send(a -> a.deposit(3));
      } catch (BufferFullException e) { // names the object, its capacity and the policy
        rejected = true;
      }
      // end::reject[]

      CountDownLatch latestBusy = new CountDownLatch(1);
      ActiveObject<Account> latest = runtime.spawn(new Account(), latestWins);
      latest.send(
          a -> {
            latestBusy.countDown();
            release.await();
          });
      latestBusy.await();
      for (int i = 1; i <= 4; i++) {
        long amount = i;
        latest.send(a -> a.deposit(amount)); // 3 drops 1, 4 drops 2
      }
      long droppedWhileBusy = dropped.get();
      release.countDown();
      return new Seen(rejected, droppedWhileBusy, fromText);
    }
  }
}
