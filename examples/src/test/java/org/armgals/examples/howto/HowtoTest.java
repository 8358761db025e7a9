package org.armgals.examples.howto;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.armgals.active.OverflowPolicy;
import org.junit.jupiter.api.Test;

/** The snippets quoted in README.md and docs/ do what the text around them says. */
class HowtoTest {

  @Test
  void quickStartCountsToFortyTwo() {
    PrintStream stdout = System.out;
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    System.setOut(new PrintStream(bytes, true, StandardCharsets.UTF_8));
    try {
      QuickStart.main(new String[0]);
    } finally {
      System.setOut(stdout);
    }
    assertThat(bytes.toString(StandardCharsets.UTF_8).lines()).contains("count = 2", "total = 42");
  }

  @Test
  void basicsDepositWithdrawOnceTheGuardHoldsAndComposeAsStages() throws Exception {
    Basics.Seen seen = Basics.run();
    assertThat(seen.afterDeposits()).isEqualTo(100);
    assertThat(seen.leftAfterGuarded()).isEqualTo(20);
    assertThat(seen.fromStage()).isEqualTo(20);
  }

  @Test
  void paperStyleWithdrawWaitsForTheDeposit() {
    assertThat(PaperStyle.run()).isEqualTo(70);
  }

  @Test
  void dataEventsWaitWhilePausedThenArriveInOrder() {
    assertThat(DataEvents.run()).containsExactly("hall 19.5", "attic 23.0");
  }

  @Test
  void proxyTurnsCallsIntoRequests() {
    assertThat(Proxying.run()).isEqualTo(70);
  }

  @Test
  void overflowPoliciesRejectAndDropOldest() throws InterruptedException {
    Overflow.Seen seen = Overflow.run();
    assertThat(seen.rejected()).isTrue();
    assertThat(seen.dropped()).isEqualTo(2);
    assertThat(seen.parsed()).isEqualTo(OverflowPolicy.block(java.time.Duration.ofSeconds(2)));
  }

  @Test
  void thermostatReactsAtTheInstantThatTakesTheReading() {
    assertThat(Reactive.run()).containsExactly("instant 1: heater on", "instant 2: heater off");
  }

  @Test
  void failureReachesTheCallerAndTheHandlerAndTheObjectGoesOn() {
    Errors.Seen seen = Errors.run();
    assertThat(seen.cause()).isEqualTo("amount must be > 0, was -5");
    assertThat(seen.balanceAfter()).isZero();
    assertThat(seen.handled()).singleElement().asString().endsWith("amount must be > 0, was -5");
    assertThat(seen.refused()).isTrue();
    assertThat(seen.clean()).isTrue();
  }
}
