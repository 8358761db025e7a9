package org.armgals.examples.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.armgals.active.TimeSource;
import org.armgals.examples.live.LiveServer;
import org.armgals.examples.live.Player;
import org.armgals.examples.run.Example;
import org.armgals.examples.sim.Playback;
import org.armgals.examples.sim.Replay;
import org.armgals.examples.sim.SimExample;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code armgals view <trace>}: plays a run's trace back in the live view's page, with pause and
 * step, until Ctrl-C.
 */
@Command(
    name = "view",
    description =
        "Plays a run's trace back in a browser, as 'run --live' shows a run, with pause and step;"
            + " serves the page on 127.0.0.1 until Ctrl-C.")
final class ViewCommand implements Callable<Integer> {
  @Mixin HelpOption help = new HelpOption();

  private final Catalog catalog;
  private final PrintStream out;

  @Parameters(
      index = "0",
      paramLabel = "<trace>",
      description = "a run's output directory, or the trace.jsonl in it")
  Path trace = Path.of("");

  @Option(
      names = "--live-port",
      paramLabel = "<port>",
      defaultValue = "0",
      description = "the port of the page (default: a free one)")
  int port;

  @Option(names = "--paused", description = "start paused, at the first cycle")
  boolean paused;

  ViewCommand(Catalog catalog, PrintStream out) {
    this.catalog = catalog;
    this.out = out;
  }

  @Override
  public Integer call() throws InterruptedException {
    TraceFile read = TraceFile.read(trace, catalog);
    Path file = read.file();
    Replay.Header header = read.header();
    Example example = read.example();
    if (!(example instanceof SimExample simulated)) {
      throw new UsageException("'" + example.name() + "' does not run on the simulator");
    }
    Playback playback =
        Playback.read(simulated, header, read.text(), file.toAbsolutePath().getParent());
    try (LiveServer server = LiveServer.start(port)) {
      Player player = new Player(playback, server, header.period(), TimeSource.system(), paused);
      server.onControl(player::command);
      out.println(
          "armgals: playing "
              + file
              + " ("
              + playback.size()
              + " cycles of '"
              + example.name()
              + "') at "
              + server.address()
              + "; Ctrl-C stops");
      out.flush();
      player.play();
    }
    return 0;
  }
}
