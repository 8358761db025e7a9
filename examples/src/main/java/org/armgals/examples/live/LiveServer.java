package org.armgals.examples.live;

import static java.util.Objects.requireNonNull;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.armgals.examples.sim.RunWatcher;
import org.jspecify.annotations.Nullable;

/**
 * The live view's web server: the JDK's {@link HttpServer} on 127.0.0.1, serving the page (plain
 * HTML, JavaScript and SVG from the jar, nothing from the internet) and the run's events as
 * server-sent events on {@code /events}: {@code start}, {@code loop} (the records of the reflective
 * loop, each once, in order), {@code frame} (the latest only: a browser that falls behind skips
 * frames, never records) and {@code end}. A browser that connects late gets the start and every
 * record so far. {@code POST /control?do=pause|play|step|faster|slower} goes to the {@link
 * #onControl control} (the player of {@code armgals view}).
 *
 * <p>As a {@link RunWatcher} it returns at once: each browser has a virtual thread of its own that
 * sends what is new, at most {@value #FRAMES_PER_SECOND} frames a second.
 */
public final class LiveServer implements RunWatcher, AutoCloseable {
  /** The most frames a second a browser is sent. */
  static final int FRAMES_PER_SECOND = 25;

  private static final Map<String, String> PAGES =
      Map.of(
          "/", "index.html",
          "/index.html", "index.html",
          "/live.js", "live.js",
          "/live.css", "live.css");

  private final HttpServer server;
  private final ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();
  private final ReentrantLock lock = new ReentrantLock();
  private final Condition changed = lock.newCondition();
  private final List<String> loop = new ArrayList<>();
  private @Nullable String start;
  private @Nullable String frame;
  private long frames;
  private @Nullable String end;
  private boolean closed;
  private volatile Consumer<String> control = command -> {};

  private LiveServer(HttpServer server) {
    this.server = server;
  }

  /**
   * Starts serving on 127.0.0.1 at {@code port}, or at a free port if it is 0.
   *
   * @throws IllegalArgumentException {@code port} is not 0 to 65535, or is taken
   * @throws UncheckedIOException the server cannot be started
   */
  public static LiveServer start(int port) {
    if (port < 0 || port > 65_535) {
      throw new IllegalArgumentException(
          "--live-port must be a port from 1 to 65535, or 0 for a free one; was " + port);
    }
    HttpServer http;
    try {
      http = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 16);
    } catch (BindException e) {
      throw new IllegalArgumentException(
          "--live-port "
              + port
              + ": cannot listen on 127.0.0.1:"
              + port
              + " ("
              + e.getMessage()
              + "); give another port, or 0 for a free one");
    } catch (IOException e) {
      throw new UncheckedIOException("cannot start the live view's server on 127.0.0.1", e);
    }
    LiveServer live = new LiveServer(http);
    http.setExecutor(live.threads);
    http.createContext("/", live::page);
    http.createContext("/events", live::events);
    http.createContext("/control", live::control);
    http.start();
    return live;
  }

  /** Where a browser finds the page: {@code http://127.0.0.1:<port>/}. */
  public URI address() {
    return URI.create("http://127.0.0.1:" + server.getAddress().getPort() + "/");
  }

  /**
   * Sends {@code control} the commands of the page's buttons: pause, play, step, faster, slower.
   */
  public void onControl(Consumer<String> control) {
    this.control = requireNonNull(control, "control");
  }

  @Override
  public void started(String start) {
    update(() -> this.start = requireNonNull(start, "start"));
  }

  @Override
  public void frame(long cycle, String frame) {
    requireNonNull(frame, "frame");
    update(
        () -> {
          this.frame = frame;
          frames++;
        });
  }

  @Override
  public void loop(String record) {
    requireNonNull(record, "record");
    update(() -> loop.add(record));
  }

  @Override
  public void ended(String end) {
    update(() -> this.end = requireNonNull(end, "end"));
  }

  /** Stops serving: each browser is sent what it has not had yet, then its stream ends. */
  @Override
  public void close() {
    update(() -> closed = true);
    server.stop(1);
    threads.shutdownNow();
  }

  private void update(Runnable change) {
    lock.lock();
    try {
      change.run();
      changed.signalAll();
    } finally {
      lock.unlock();
    }
  }

  private void page(HttpExchange exchange) throws IOException {
    try (exchange) {
      String name = PAGES.get(exchange.getRequestURI().getPath());
      if (name == null || !"GET".equals(exchange.getRequestMethod())) {
        send(exchange, 404, "text/plain", "not found\n".getBytes(StandardCharsets.UTF_8));
        return;
      }
      byte[] body;
      try (InputStream in = LiveServer.class.getResourceAsStream(name)) {
        if (in == null) {
          throw new IllegalStateException("the jar has no " + name + " beside " + LiveServer.class);
        }
        body = in.readAllBytes();
      }
      String type =
          name.endsWith(".html")
              ? "text/html; charset=utf-8"
              : name.endsWith(".js") ? "text/javascript; charset=utf-8" : "text/css; charset=utf-8";
      send(exchange, 200, type, body);
    }
  }

  private void control(HttpExchange exchange) throws IOException {
    try (exchange) {
      String query = exchange.getRequestURI().getQuery();
      String command = query != null && query.startsWith("do=") ? query.substring(3) : "";
      if (!"POST".equals(exchange.getRequestMethod())
          || !List.of("pause", "play", "step", "faster", "slower").contains(command)) {
        send(
            exchange,
            400,
            "text/plain",
            "expected POST /control?do=pause|play|step|faster|slower\n"
                .getBytes(StandardCharsets.UTF_8));
        return;
      }
      control.accept(command);
      exchange.sendResponseHeaders(204, -1);
    }
  }

  private static void send(HttpExchange exchange, int status, String type, byte[] body)
      throws IOException {
    exchange.getResponseHeaders().set("Content-Type", type);
    exchange.getResponseHeaders().set("Cache-Control", "no-store");
    exchange.sendResponseHeaders(status, body.length);
    exchange.getResponseBody().write(body);
  }

  /**
   * One browser's stream: what is new, as it comes, until the server closes or the browser goes.
   */
  private void events(HttpExchange exchange) throws IOException {
    try (exchange) {
      exchange.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
      exchange.getResponseHeaders().set("Cache-Control", "no-store");
      exchange.sendResponseHeaders(200, 0);
      OutputStream out = exchange.getResponseBody();
      boolean startSent = false;
      boolean endSent = false;
      int loopSent = 0;
      long frameSent = 0;
      long gap = 1_000_000_000L / FRAMES_PER_SECOND;
      while (true) {
        StringBuilder batch = new StringBuilder();
        boolean last;
        lock.lock();
        try {
          while (!closed
              && (start == null || startSent)
              && loop.size() == loopSent
              && frames == frameSent
              && (end == null || endSent)) {
            if (changed.awaitNanos(15_000_000_000L) <= 0) {
              batch.append(": still here\n\n"); // a comment, so that a dead browser is noticed
              break;
            }
          }
          if (start != null && !startSent) {
            event(batch, "start", start);
            startSent = true;
          }
          if (loop.size() > loopSent) {
            event(batch, "loop", "[" + String.join(",", loop.subList(loopSent, loop.size())) + "]");
            loopSent = loop.size();
          }
          if (frames != frameSent && frame != null) {
            event(batch, "frame", frame);
            frameSent = frames;
          }
          if (end != null && !endSent) {
            event(batch, "end", end);
            endSent = true;
          }
          last = closed;
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
          return;
        } finally {
          lock.unlock();
        }
        out.write(batch.toString().getBytes(StandardCharsets.UTF_8));
        out.flush();
        if (last) {
          return;
        }
        java.util.concurrent.locks.LockSupport.parkNanos(gap); // at most so many frames a second
      }
    } catch (IOException gone) {
      // the browser went away: its thread ends, the run goes on
    }
  }

  private static void event(StringBuilder batch, String name, String data) {
    batch.append("event: ").append(name).append('\n').append("data: ").append(data).append("\n\n");
  }
}
