package org.armgals.examples.cli;

import java.io.PrintStream;
import java.math.BigDecimal;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.armgals.examples.run.Example;
import org.armgals.examples.sim.Replay;
import org.armgals.examples.sim.SimExample;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;

/**
 * {@code armgals replay <trace>}: runs again the run that wrote a trace and says whether it wrote
 * the same trace, bit for bit (status 0) or from which cycle it differs (status 1).
 */
@Command(
    name = "replay",
    description = "Re-runs the run that wrote a trace and says whether it reproduces it exactly.")
final class ReplayCommand implements Callable<Integer> {
  @Mixin HelpOption help = new HelpOption();

  private final Catalog catalog;
  private final PrintStream out;

  @Parameters(
      index = "0",
      paramLabel = "<trace>",
      description = "a trace.jsonl of 'armgals run', or the directory it wrote it in")
  Path trace = Path.of("");

  ReplayCommand(Catalog catalog, PrintStream out) {
    this.catalog = catalog;
    this.out = out;
  }

  @Override
  public Integer call() {
    TraceFile read = TraceFile.read(trace, catalog);
    Replay.Header header = read.header();
    Example example = read.example();
    if (!(example instanceof SimExample simulated)) {
      throw new UsageException(
          "'" + example.name() + "' does not run on the simulator: it has no trace to replay");
    }
    out.printf(
        Locale.ROOT,
        "replaying %s: '%s', %d cycles of %s ms, seed %d%n",
        read.file(),
        example.name(),
        header.cycles(),
        BigDecimal.valueOf(header.period().toNanos(), 6).stripTrailingZeros().toPlainString(),
        header.seed());
    Replay.Verdict verdict =
        Replay.replay(simulated, header, read.text(), read.file().toAbsolutePath().getParent());
    out.println(verdict.line());
    return verdict instanceof Replay.Differs ? Armgals.FAILED : 0;
  }
}
