package org.armgals.examples.live;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Headless Chromium driven by Debian's chromedriver over the W3C WebDriver protocol (JSON over HTTP
 * on 127.0.0.1), with the JDK's HTTP client: the few commands the live view's tests need. Without
 * Chromium or chromedriver it fails, saying what to install.
 */
final class Browser implements AutoCloseable {
  static final Path CHROMIUM = Path.of(System.getProperty("armgals.chromium", "/usr/bin/chromium"));
  static final Path DRIVER =
      Path.of(System.getProperty("armgals.chromedriver", "/usr/bin/chromedriver"));

  private static final Pattern SESSION = Pattern.compile("\"sessionId\"\\s*:\\s*\"([^\"]+)\"");
  private static final Pattern STRING =
      Pattern.compile("\"value\"\\s*:\\s*\"((?:[^\"\\\\]++|\\\\.)*+)\"");

  private final Process driver;
  private final HttpClient http = HttpClient.newHttpClient();
  private final String base;
  private final String session;
  private final Path profile;

  private Browser(Process driver, String base, String session, Path profile) {
    this.driver = driver;
    this.base = base;
    this.session = session;
    this.profile = profile;
  }

  /** Starts chromedriver on a free port of 127.0.0.1 and a headless Chromium session. */
  static Browser start() throws IOException, InterruptedException {
    if (!Files.isExecutable(CHROMIUM) || !Files.isExecutable(DRIVER)) {
      throw new AssertionError(
          "the live view's tests need headless Chromium and its driver at "
              + CHROMIUM
              + " and "
              + DRIVER
              + ": install Debian's packages with 'apt-get install -y chromium chromium-driver'"
              + " (.ci/run does when they are missing)");
    }
    int port;
    try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      port = s.getLocalPort();
    }
    Process driver =
        new ProcessBuilder(DRIVER.toString(), "--port=" + port, "--allowed-ips=127.0.0.1")
            .redirectErrorStream(true)
            .redirectOutput(ProcessBuilder.Redirect.DISCARD)
            .start();
    String base = "http://127.0.0.1:" + port;
    HttpClient http = HttpClient.newHttpClient();
    long deadline = System.nanoTime() + Duration.ofSeconds(30).toNanos();
    while (true) {
      try {
        String status = get(http, base + "/status");
        if (status.contains("\"ready\":true") || status.contains("\"ready\": true")) {
          break;
        }
      } catch (IOException notYet) {
        // chromedriver is starting
      }
      if (System.nanoTime() > deadline || !driver.isAlive()) {
        driver.destroyForcibly();
        throw new AssertionError("chromedriver did not start on 127.0.0.1:" + port);
      }
      Thread.sleep(50); // polling a process that has no other way to say it is ready
    }
    Path profile = Files.createTempDirectory("armgals-chromium");
    String capabilities =
        "{\"capabilities\":{\"alwaysMatch\":{\"goog:chromeOptions\":{\"binary\":\""
            + CHROMIUM
            + "\",\"args\":[\"--headless\",\"--no-sandbox\",\"--disable-gpu\",\"--disable-quic\","
            + "\"--no-first-run\",\"--disable-background-networking\","
            + "\"--disable-component-update\",\"--disable-sync\",\"--window-size=1280,900\","
            + "\"--user-data-dir="
            + profile
            + "\"]}}}}";
    String answer = post(http, base + "/session", capabilities);
    Matcher m = SESSION.matcher(answer);
    if (!m.find()) {
      driver.destroyForcibly();
      throw new AssertionError("chromedriver started no session: " + answer);
    }
    return new Browser(driver, base, m.group(1), profile);
  }

  /** Loads {@code page}. */
  void open(URI page) throws IOException, InterruptedException {
    post(http, base + "/session/" + session + "/url", "{\"url\":\"" + page + "\"}");
  }

  /** Runs {@code script} (a function body that returns a value) and answers it as text. */
  String text(String script) throws IOException, InterruptedException {
    String body = "{\"script\":\"" + script.replace("\"", "\\\"") + "\",\"args\":[]}";
    String answer = post(http, base + "/session/" + session + "/execute/sync", body);
    Matcher m = STRING.matcher(answer);
    if (!m.find()) {
      throw new AssertionError("the script answered no text: " + answer);
    }
    return m.group(1);
  }

  /** A screenshot of the page as it is, as PNG. */
  byte[] screenshot() throws IOException, InterruptedException {
    String answer = get(http, base + "/session/" + session + "/screenshot");
    int from = answer.indexOf("\"value\":\"");
    int to = from < 0 ? -1 : answer.indexOf('"', from + 9);
    if (to < 0) { // base64 holds no quote; a regex would recurse over a megabyte of it
      throw new AssertionError("no screenshot: " + answer);
    }
    return Base64.getDecoder().decode(answer.substring(from + 9, to));
  }

  @Override
  public void close() throws IOException {
    try {
      http.send(
          HttpRequest.newBuilder(URI.create(base + "/session/" + session)).DELETE().build(),
          HttpResponse.BodyHandlers.ofString());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      driver.destroy();
      try {
        driver.waitFor();
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
      try (var files = Files.walk(profile)) {
        files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
      }
    }
  }

  private static String get(HttpClient http, String url) throws IOException, InterruptedException {
    return http.send(
            HttpRequest.newBuilder(URI.create(url)).timeout(Duration.ofSeconds(60)).build(),
            HttpResponse.BodyHandlers.ofString())
        .body();
  }

  private static String post(HttpClient http, String url, String json)
      throws IOException, InterruptedException {
    return http.send(
            HttpRequest.newBuilder(URI.create(url))
                .timeout(Duration.ofSeconds(60))
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(json))
                .build(),
            HttpResponse.BodyHandlers.ofString())
        .body();
  }
}
