package org.armgals.bench.broker;

import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.armgals.active.TimeSource;
import org.armgals.bench.Args;

/**
 * Runs the broker benchmark over one embedded broker and prints one line per run:
 *
 * <pre>
 * [warmup ]broker name=events impl=&lt;impl&gt; transport=&lt;invm|netty&gt; guarantee=&lt;amo|alo&gt; ops_per_s=&lt;x&gt;
 * [warmup ]broker name=futurertt impl=&lt;impl&gt; transport=&lt;invm|netty&gt; guarantee=&lt;amo|alo&gt; p50_us=&lt;x&gt; p99_us=&lt;y&gt;
 * </pre>
 *
 * <p>Usage: {@code BrokerBench [--warmup n] [--runs n] [--messages n] [--requests n] [--guarantee
 * amo|alo|both] [name...]} where a name is {@code events} or {@code futurertt} (default: both).
 * Every round runs each workload with each guarantee (default both; at least once with a hundredth
 * of the messages and requests) on each transport with each implementation, one after the other, so
 * that all of them see much the same load; {@code --warmup} rounds (default 2) are printed with a
 * {@code warmup} prefix, then {@code --runs} rounds (default 3) are measured. {@code --messages}
 * (default 200000) events per events run, {@code --requests} (default 20000) round trips per
 * futurertt run. Exits with status 1 if a run fails.
 */
public final class BrokerBench {
  /** The size of every event's and every reply's payload. */
  public static final int PAYLOAD_BYTES = 64;

  /** The workloads, in the order they run. */
  public static final List<String> WORKLOADS = List.of("events", "futurertt");

  /**
   * At-least-once runs use this share of {@code --messages} and {@code --requests}: every
   * persistent message is synced to disk before the broker confirms it.
   */
  static final int ALO_SHARE = 100;

  private final List<BrokerImpl> impls;
  private final List<Guarantee> guarantees;
  private final BenchBroker broker;
  private final PrintStream out;
  private final int messages;
  private final int requests;

  BrokerBench(
      List<BrokerImpl> impls,
      List<Guarantee> guarantees,
      BenchBroker broker,
      PrintStream out,
      int messages,
      int requests) {
    this.impls = List.copyOf(impls);
    this.guarantees = List.copyOf(guarantees);
    this.broker = broker;
    this.out = out;
    this.messages = messages;
    this.requests = requests;
  }

  /** Entry point; see the class comment. */
  public static void main(String[] args) throws Exception {
    int warmup = 2;
    int runs = 3;
    int messages = 200_000;
    int requests = 20_000;
    List<Guarantee> guarantees = List.of(Guarantee.values());
    List<String> names = new ArrayList<>();
    for (int i = 0; i < args.length; i++) {
      switch (args[i]) {
        case "--warmup" -> warmup = Args.count(Args.value(args, ++i, "--warmup"), "--warmup", 0);
        case "--runs" -> runs = Args.count(Args.value(args, ++i, "--runs"), "--runs", 1);
        case "--messages" ->
            messages = Args.count(Args.value(args, ++i, "--messages"), "--messages", 1);
        case "--guarantee" -> guarantees = guarantees(Args.value(args, ++i, "--guarantee"));
        case "--requests" ->
            requests = Args.count(Args.value(args, ++i, "--requests"), "--requests", 1);
        default -> names.add(known(args[i]));
      }
    }
    if (names.isEmpty()) {
      names.addAll(WORKLOADS);
    }
    TimeSource time = TimeSource.system();
    try (BenchBroker broker = BenchBroker.start(freePort(), freePort())) {
      BrokerBench bench =
          new BrokerBench(
              List.of(new RawJms(time), new ArmgalsJms(time)),
              guarantees,
              broker,
              System.out,
              messages,
              requests);
      for (int round = 0; round < warmup + runs; round++) {
        bench.round(names, round < warmup ? "warmup " : "");
      }
    } catch (Exception e) {
      org.slf4j.LoggerFactory.getLogger(BrokerBench.class).error("broker: the run failed", e);
      System.exit(1);
    }
    // Artemis's and the runtimes' lingering threads must not keep a finished run alive.
    System.exit(0);
  }

  /** Each workload, on each transport, with each implementation. */
  void round(List<String> names, String prefix) throws Exception {
    for (String name : names) {
      for (Guarantee guarantee : guarantees) {
        for (Transport transport : Transport.values()) {
          for (BrokerImpl impl : impls) {
            System.gc();
            if (name.equals("events")) {
              int n = guarantee == Guarantee.ALO ? Math.max(1, messages / ALO_SHARE) : messages;
              double rate = impl.events(broker, transport, guarantee, n);
              out.printf(
                  Locale.ROOT,
                  "%sbroker name=events impl=%s transport=%s guarantee=%s ops_per_s=%.0f%n",
                  prefix,
                  impl.name(),
                  transport.label(),
                  guarantee.label(),
                  rate);
            } else {
              int n = guarantee == Guarantee.ALO ? Math.max(1, requests / ALO_SHARE) : requests;
              long[] nanos = impl.futureRoundTrips(broker, transport, guarantee, n);
              Arrays.sort(nanos);
              out.printf(
                  Locale.ROOT,
                  "%sbroker name=futurertt impl=%s transport=%s guarantee=%s p50_us=%.1f"
                      + " p99_us=%.1f%n",
                  prefix,
                  impl.name(),
                  transport.label(),
                  guarantee.label(),
                  percentile(nanos, 0.50) / 1e3,
                  percentile(nanos, 0.99) / 1e3);
            }
          }
        }
      }
    }
  }

  /** The {@code p}-quantile of sorted values (nearest rank). */
  static long percentile(long[] sorted, double p) {
    int rank = (int) Math.ceil(p * sorted.length);
    return sorted[Math.max(0, rank - 1)];
  }

  private static int freePort() throws IOException {
    try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      return socket.getLocalPort();
    }
  }

  private static List<Guarantee> guarantees(String text) {
    return switch (text) {
      case "amo" -> List.of(Guarantee.AMO);
      case "alo" -> List.of(Guarantee.ALO);
      case "both" -> List.of(Guarantee.values());
      default ->
          throw new IllegalArgumentException(
              "unknown guarantee '" + text + "'; expected amo, alo or both");
    };
  }

  private static String known(String name) {
    if (!WORKLOADS.contains(name)) {
      throw new IllegalArgumentException(
          "unknown workload '" + name + "'; expected one of " + WORKLOADS);
    }
    return name;
  }
}
