package org.armgals.examples.live;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.armgals.active.TimeSource;
import org.armgals.examples.cli.Armgals;
import org.armgals.examples.cli.Catalog;
import org.armgals.examples.sim.Playback;
import org.armgals.examples.sim.Replay;
import org.armgals.examples.sim.SimExample;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The live view in a real browser: headless Chromium loads the page while a robot runs. */
class LiveViewTest {
  private static final Pattern ADDRESS = Pattern.compile("the live view is at (http://\\S+)");

  @TempDir Path dir;

  @Test
  void aLiveRunShowsItsCycleCounterAdvancingAndItsMoleculeDrawn() throws Exception {
    Output output = new Output();
    PrintStream out = new PrintStream(output, true, StandardCharsets.UTF_8);
    CompletableFuture<Integer> run =
        CompletableFuture.supplyAsync(
            () ->
                Armgals.execute(
                    Catalog.standard(),
                    out,
                    out,
                    "run",
                    "energy",
                    "--live",
                    "--seconds",
                    "8",
                    "--out",
                    dir.resolve("energy").toString()));
    URI page = awaitAddress(output, run);
    assertThat(page.getHost()).isEqualTo("127.0.0.1");
    try (Browser browser = Browser.start()) {
      browser.open(page);
      long first = awaitCycle(browser, -1);
      long later = awaitCycle(browser, first);
      assertThat(later).isGreaterThan(first);
      assertThat(browser.text("return '' + document.querySelectorAll('#top circle.kernel').length"))
          .isEqualTo("1");
      assertThat(browser.text("return '' + document.querySelectorAll('#side line.leg').length"))
          .isEqualTo("6");
      assertThat(browser.text("return document.getElementById('example').textContent"))
          .isEqualTo("energy");
      assertThat(
              Long.parseLong(
                  browser.text("return '' + document.querySelectorAll('#loop tbody tr').length")))
          .isPositive();
      String shot = System.getProperty("armgals.liveScreenshot", "");
      if (!shot.isEmpty()) {
        Files.write(Path.of(shot), browser.screenshot());
      }
    }
    assertThat(run.get()).as(output.text()).isZero();
    assertThat(dir.resolve("energy").resolve("programs.jsonl")).isNotEmptyFile();
  }

  @Test
  void aTracePlayedBackPausedAdvancesOneCycleAStep() throws Exception {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
    Path runDir = dir.resolve("walker");
    assertThat(
            Armgals.execute(
                Catalog.standard(),
                out,
                out,
                "run",
                "walker",
                "--cycles",
                "20",
                "--out",
                runDir.toString()))
        .as(bytes.toString(StandardCharsets.UTF_8))
        .isZero();
    String text = Files.readString(runDir.resolve("trace.jsonl"));
    Replay.Header header = Replay.Header.parse(text.lines().findFirst().orElseThrow());
    SimExample walker = (SimExample) Catalog.standard().find("walker").orElseThrow();
    Playback playback = Playback.read(walker, header, text, runDir);
    assertThat(playback.size()).isEqualTo(20);
    try (LiveServer server = LiveServer.start(0);
        Browser browser = Browser.start()) {
      Player player = new Player(playback, server, header.period(), TimeSource.system(), true);
      server.onControl(player::command);
      Thread playing = Thread.ofVirtual().start(() -> play(player));
      try {
        browser.open(server.address());
        awaitText(browser, "return document.getElementById('state').textContent", "playing");
        assertThat(
                browser.text(
                    "return document.getElementById('controls').hidden ? 'hidden' : 'shown'"))
            .isEqualTo("shown");
        browser.text("document.getElementById('step').click(); return 'clicked'");
        awaitText(browser, "return document.getElementById('cycle').textContent", "0");
        browser.text("document.getElementById('step').click(); return 'clicked'");
        awaitText(browser, "return document.getElementById('cycle').textContent", "1");
        assertThat(
                browser.text("return '' + document.querySelectorAll('#top circle.kernel').length"))
            .isEqualTo("1");
        browser.text("document.getElementById('play').click(); return 'clicked'");
        awaitText(browser, "return document.getElementById('state').textContent", "ended");
        assertThat(browser.text("return document.getElementById('cycle').textContent"))
            .isEqualTo("19");
      } finally {
        player.stop();
        playing.join();
      }
    }
  }

  private static void play(Player player) {
    try {
      player.play();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /** What the run prints, kept, with the live view's address as soon as the run prints it. */
  private static final class Output extends OutputStream {
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    final CompletableFuture<URI> address = new CompletableFuture<>();

    @Override
    public synchronized void write(int b) {
      bytes.write(b);
      if (b == '\n' && !address.isDone()) {
        Matcher m = ADDRESS.matcher(text());
        if (m.find()) {
          address.complete(URI.create(m.group(1)));
        }
      }
    }

    synchronized String text() {
      return bytes.toString(StandardCharsets.UTF_8);
    }
  }

  /** The live view's address, once the run prints it; fails if the run ends first. */
  private static URI awaitAddress(Output output, CompletableFuture<Integer> run)
      throws InterruptedException {
    CompletableFuture<URI> ended =
        run.thenApply(
            status -> {
              throw new AssertionError(
                  "the run ended (" + status + ") without a live view: " + output.text());
            });
    try {
      return output.address.applyToEither(ended, address -> address).get(120, TimeUnit.SECONDS);
    } catch (ExecutionException e) {
      throw new AssertionError(e.getCause().getMessage(), e.getCause());
    } catch (TimeoutException e) {
      throw new AssertionError("the run printed no address in 120 s: " + output.text(), e);
    }
  }

  /** Waits until the page's cycle counter shows a number above {@code above}, and answers it. */
  private static long awaitCycle(Browser browser, long above) throws Exception {
    long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
    String shown = "";
    while (System.nanoTime() < deadline) {
      shown = browser.text("return document.getElementById('cycle').textContent");
      if (shown.matches("\\d+") && Long.parseLong(shown) > above) {
        return Long.parseLong(shown);
      }
      Thread.sleep(50); // the page updates as the run's frames arrive
    }
    throw new AssertionError("the cycle counter stayed at '" + shown + "', not above " + above);
  }

  private static void awaitText(Browser browser, String script, String expected) throws Exception {
    long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
    String shown = "";
    while (System.nanoTime() < deadline) {
      shown = browser.text(script);
      if (shown.equals(expected)) {
        return;
      }
      Thread.sleep(50); // the page updates as the player's frames arrive
    }
    throw new AssertionError("the page showed '" + shown + "', not '" + expected + "'");
  }
}
