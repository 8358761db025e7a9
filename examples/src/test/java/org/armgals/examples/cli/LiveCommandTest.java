package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line of the live view: {@code run --live} and {@code view}, and their errors. */
class LiveCommandTest {
  private record Result(int status, String out, String err) {}

  @TempDir Path dir;

  private static Result armgals(String... args) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status = Armgals.execute(Catalog.standard(), o, e, args);
    }
    return new Result(
        status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
  }

  @Test
  void aPortOutOfRangeIsAUsageErrorNamingIt() {
    Result r = armgals("run", "energy", "--live", "--live-port", "70000", "--out", dir + "/x");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err()).contains("--live-port must be a port from 1 to 65535").contains("70000");
    assertThat(dir.resolve("x")).doesNotExist();
  }

  @Test
  void aTakenPortIsAUsageErrorNamingIt() throws IOException {
    try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      int port = taken.getLocalPort();
      Result r = armgals("run", "energy", "--live", "--live-port", "" + port, "--out", dir + "/x");
      assertThat(r.status()).isEqualTo(Armgals.USAGE);
      assertThat(r.err()).contains("--live-port " + port).contains("cannot listen on 127.0.0.1");
    }
  }

  @Test
  void speedAndPortWithoutLiveAreUsageErrors() {
    Result speed = armgals("run", "energy", "--speed", "2");
    assertThat(speed.status()).isEqualTo(Armgals.USAGE);
    assertThat(speed.err()).contains("--speed applies to a live run: add --live");
    Result bad = armgals("run", "energy", "--live", "--speed", "0");
    assertThat(bad.status()).isEqualTo(Armgals.USAGE);
    assertThat(bad.err()).contains("--speed must be a finite number above 0, was 0");
  }

  @Test
  void aDemoHasNothingToShowLive() {
    Result r = armgals("run", "demo", "--live");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err()).contains("'demo' does not run on the simulator");
  }

  @Test
  void viewingAMissingTraceIsAUsageErrorSayingWhatWasExpected() throws IOException {
    Result file = armgals("view", dir.resolve("none.jsonl").toString());
    assertThat(file.status()).isEqualTo(Armgals.USAGE);
    assertThat(file.err()).contains("no trace at").contains("none.jsonl");
    Path empty = Files.createDirectory(dir.resolve("empty"));
    Result directory = armgals("view", empty.toString());
    assertThat(directory.status()).isEqualTo(Armgals.USAGE);
    assertThat(directory.err()).contains("no trace in " + empty);
    Files.writeString(dir.resolve("other.jsonl"), "{\"type\":\"header\"}\n");
    Result other = armgals("view", dir.resolve("other.jsonl").toString());
    assertThat(other.status()).isEqualTo(Armgals.USAGE);
    assertThat(other.err()).contains("other.jsonl: ");
  }

  @Test
  void viewsHelpListsItsOptions() {
    Result r = armgals("view", "--help");
    assertThat(r.status()).isZero();
    assertThat(r.out()).contains("--live-port").contains("--paused").contains("Exit status:");
  }
}
