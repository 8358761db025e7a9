package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.concurrent.CompletionException;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Futures in the asynchronous world (docs/architecture.md, runtime semantics 2). */
class FutureContractTest {
  private final ActiveRuntime runtime = ActiveRuntime.builder().workers(1).jmx(false).build();

  @AfterEach
  void shutdown() {
    runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(10));
  }

  static final class Cell {
    int value;
    boolean open;
  }

  /** Asks another object and waits by necessity for its answer. */
  static final class Asker {
    ActiveRef<Cell> other;

    Asker(ActiveRef<Cell> other) {
      this.other = other;
    }

    int askTwice() {
      return other.call(c -> c.value).getValue() + other.call(c -> c.value).getValue();
    }
  }

  @Test
  void getValueWaitsByNecessityUntilTheValueIsThere() {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    FutureValue<Integer> f = cell.callWhen(c -> c.open, c -> c.value);
    assertThat(f.isDone()).isFalse();
    cell.send(
        c -> {
          c.value = 42;
          c.open = true;
        });
    assertThat(f.getValue(Duration.ofSeconds(10))).isEqualTo(42);
    assertThat(f.isDone()).isTrue();
  }

  @Test
  void getValueGivesUpAfterItsTimeoutNamingTheObject() {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    FutureValue<Integer> f = cell.callWhen(c -> c.open, c -> c.value);
    assertThatThrownBy(() -> f.getValue(Duration.ofMillis(50)))
        .isInstanceOf(FutureTimeoutException.class)
        .hasMessageContaining(cell.address().toString());
    assertThatThrownBy(() -> f.touch(Duration.ofMillis(-1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("PT-0.001S");
  }

  @Test
  void signalCompletesWhenTheRequestHasRun() {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    Future done = cell.signal(c -> c.value = 7);
    done.touch(Duration.ofSeconds(10));
    assertThat(cell.call(c -> c.value).getValue(Duration.ofSeconds(10))).isEqualTo(7);
  }

  @Test
  void waitingInsideAnObjectParksOnlyThatObject() {
    // One worker only: the asker parks inside its event, yet the cell still runs.
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    cell.send(c -> c.value = 5);
    ActiveObject<Asker> asker = runtime.spawn(new Asker(cell));
    assertThat(asker.call(Asker::askTwice).getValue(Duration.ofSeconds(10))).isEqualTo(10);
  }

  @Test
  void completionStageCarriesTheValueOrTheServantsException() throws Exception {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    cell.send(c -> c.value = 3);
    assertThat(
            cell.call(c -> c.value)
                .toCompletionStage()
                .toCompletableFuture()
                .get(10, TimeUnit.SECONDS))
        .isEqualTo(3);
    FutureValue<Integer> failing =
        cell.call(
            c -> {
              throw new ArithmeticException("divide");
            });
    assertThatThrownBy(() -> failing.toCompletionStage().toCompletableFuture().join())
        .isInstanceOf(CompletionException.class)
        .cause()
        .isInstanceOf(ArithmeticException.class)
        .hasMessage("divide");
  }

  @Test
  void stageAskedForBeforeCompletionIsCompletedLater() throws Exception {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    FutureValue<Integer> f = cell.callWhen(c -> c.open, c -> c.value);
    var stage = f.toCompletionStage().toCompletableFuture();
    assertThat(stage.isDone()).isFalse();
    cell.send(
        c -> {
          c.value = 9;
          c.open = true;
        });
    assertThat(stage.get(10, TimeUnit.SECONDS)).isEqualTo(9);
  }

  @Test
  void completedAndFailedFuturesAnswerAtOnce() {
    assertThat(FutureValue.completed("x").getValue()).isEqualTo("x");
    assertThat(FutureValue.completed(null).getValue()).isNull();
    assertThatThrownBy(() -> FutureValue.failed(new IllegalStateException("no")).getValue())
        .isInstanceOf(RequestFailedException.class)
        .cause()
        .hasMessage("no");
  }

  @Test
  void waitingOnOwnRequestIsADirectCycle() {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    FutureValue<Integer> outer =
        cell.call(c -> ActiveContext.<Cell>self().call(x -> x.value).getValue());
    assertThatThrownBy(() -> outer.getValue(Duration.ofSeconds(10)))
        .isInstanceOf(RequestFailedException.class)
        .cause()
        .isInstanceOfSatisfying(
            WaitCycleException.class,
            e -> assertThat(e.cycle()).containsExactly(cell.address(), cell.address()))
        .hasMessageContaining("wait-for cycle: " + cell.address() + " -> " + cell.address());
  }

  /** A calls B, which calls back A and waits: A is already waiting for B. */
  static final class Ping {
    ActiveRef<Pong> pong;

    int go() {
      return pong.call(Pong::back).getValue();
    }
  }

  static final class Pong {
    ActiveRef<Ping> ping;

    int back() {
      return ping.call(p -> 1).getValue();
    }
  }

  @Test
  void waitCycleThroughAnotherObjectIsReportedWithItsMembers() {
    Ping ping = new Ping();
    Pong pong = new Pong();
    ActiveObject<Ping> a = runtime.spawn(ping);
    ActiveObject<Pong> b = runtime.spawn(pong);
    ping.pong = b;
    pong.ping = a;
    Throwable thrown =
        org.assertj.core.api.Assertions.catchThrowable(
            () -> a.call(Ping::go).getValue(Duration.ofSeconds(10)));
    assertThat(thrown).isInstanceOf(RequestFailedException.class);
    WaitCycleException cycle = findCause(thrown, WaitCycleException.class);
    assertThat(cycle.cycle()).hasSize(3).contains(a.address(), b.address());
    assertThat(cycle.cycle().get(0)).isEqualTo(cycle.cycle().get(2));
  }

  @Test
  void aWaitWithoutCycleIsNotReported() {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    cell.send(c -> c.value = 1);
    ActiveObject<Asker> a1 = runtime.spawn(new Asker(cell));
    ActiveObject<Asker> a2 = runtime.spawn(new Asker(cell));
    FutureValue<Integer> f1 = a1.call(Asker::askTwice);
    FutureValue<Integer> f2 = a2.call(Asker::askTwice);
    assertThat(f1.getValue(Duration.ofSeconds(10)) + f2.getValue(Duration.ofSeconds(10)))
        .isEqualTo(4);
  }

  @Test
  void stoppedReceiverFailsTheFutureInsteadOfHanging() {
    ActiveObject<Cell> cell = runtime.spawn(new Cell());
    FutureValue<Integer> f = cell.callWhen(c -> c.open, c -> 1);
    cell.stop();
    assertThatThrownBy(() -> f.getValue(Duration.ofSeconds(10)))
        .isInstanceOf(ObjectStoppedException.class);
  }

  /** A proxied interface: futures out of the servant, futures out of the proxy. */
  interface Account {
    void deposit(int amount);

    FutureValue<Integer> balance();

    Future audit();
  }

  static final class AccountImpl implements Account {
    int balance;
    int audits;

    @Override
    public void deposit(int amount) {
      if (amount < 0) {
        throw new IllegalArgumentException("amount must be >= 0, was " + amount);
      }
      balance += amount;
    }

    @Override
    public FutureValue<Integer> balance() {
      return FutureValue.completed(balance);
    }

    @Override
    public Future audit() {
      audits++;
      return FutureValue.completed(null);
    }
  }

  @Test
  void proxyMethodsBecomeRequestsAndReturnFutures() {
    ActiveObject<AccountImpl> account = runtime.spawn(new AccountImpl());
    Account proxy = account.proxy(Account.class);
    proxy.deposit(30);
    proxy.deposit(12);
    proxy.audit().touch(Duration.ofSeconds(10));
    assertThat(proxy.balance().getValue(Duration.ofSeconds(10))).isEqualTo(42);
    assertThat(account.call(a -> a.audits).getValue(Duration.ofSeconds(10))).isEqualTo(1);
    assertThat(proxy.toString()).contains(account.address().toString());
  }

  interface Bad {
    int answer();
  }

  static final class BadImpl implements Bad {
    @Override
    public int answer() {
      return 42;
    }
  }

  @Test
  void proxyRefusesAnInterfaceItCouldNotCall() {
    ActiveObject<Object> hidden = runtime.spawn(org.armgals.active.fixture.Hidden.servant());
    assertThatThrownBy(() -> hidden.proxy(org.armgals.active.fixture.Hidden.type()))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("must be public");
  }

  @Test
  void proxyRefusesMethodsThatCannotBeAsynchronous() {
    ActiveObject<BadImpl> bad = runtime.spawn(new BadImpl());
    assertThatThrownBy(() -> bad.proxy(Bad.class))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("Bad.answer returns int");
    assertThatThrownBy(() -> bad.proxy(Account.class))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("does not implement");
  }

  private static <T extends Throwable> T findCause(Throwable t, Class<T> type) {
    for (Throwable c = t; c != null; c = c.getCause()) {
      if (type.isInstance(c)) {
        return type.cast(c);
      }
    }
    throw new AssertionError("no " + type.getSimpleName() + " in the causes of " + t, t);
  }
}
