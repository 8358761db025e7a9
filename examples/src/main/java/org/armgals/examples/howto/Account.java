package org.armgals.examples.howto;

// tag::account[]
/**
 * A bank account, written as if single-threaded: its active object runs one request at a time, so
 * the servant needs no lock, no volatile and no atomic.
 */
public final class Account {
  private long balance;

  public void deposit(long amount) {
    if (amount <= 0) {
      throw new IllegalArgumentException("amount must be > 0, was " + amount);
    }
    balance += amount;
  }

  public boolean covers(long amount) {
    return balance >= amount;
  }

  public long withdraw(long amount) {
    balance -= amount;
    return balance;
  }

  public long balance() {
    return balance;
  }
}
// end::account[]
