package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.cli.Armgals;
import org.armgals.examples.cli.Catalog;
import org.armgals.examples.cli.RunSettings;
import org.armgals.examples.sim.Journal;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.Vec3;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code distributed} robot: a chain of two atoms whose robots run in two JVMs started by the
 * crew, through an embedded broker on 127.0.0.1, in lock step with the world.
 */
class DistributedTest {
  private static final Journal QUIET =
      new Journal() {
        @Override
        public void adaptation(int atom, String what, String why) {}

        @Override
        public void note(int atom, String text) {}
      };

  @Test
  void atomsInTheirOwnJvmsCrawlTheChainForwardAndStopWithTheCrew(@TempDir Path dir) {
    RunSettings settings = settings(dir, 2);
    Distributed example = new Distributed();
    List<ProcessHandle> children;
    List<DistributedWire.Joined> joined;
    long missed;
    Vec3 start;
    Vec3 end;
    try (Simulation sim =
        Simulation.builder(example.scene(settings)).controlPeriod(settings.period()).build()) {
      start = centre(sim);
      DistributedCrew crew = (DistributedCrew) example.start(sim, settings, QUIET);
      try {
        children = crew.processes();
        joined = crew.joined();
        sim.runCycles(150); // 1.5 s of simulated time: three strokes
        missed = crew.missedCycles();
        end = centre(sim);
      } finally {
        crew.close();
      }
    }

    long self = ProcessHandle.current().pid();
    assertThat(joined).extracting(DistributedWire.Joined::atom).containsExactly(1, 2);
    assertThat(joined)
        .extracting(DistributedWire.Joined::pid)
        .doesNotContain(self)
        .doesNotHaveDuplicates()
        .containsExactlyElementsOf(children.stream().map(ProcessHandle::pid).toList());
    assertThat(children).noneMatch(ProcessHandle::isAlive);
    // In lock step the world waits for every answer, so none is missed on a quiet machine; a
    // loaded one may miss a few (an answer later than ten seconds), not most.
    assertThat(missed).isLessThan(30);
    // Seen: 5.7 cm towards -x in 1.5 s, as with the robots in the world's own process (lock step
    // makes it the same run), and 2.5 cm of sideways drift.
    assertThat(start.x() - end.x()).isGreaterThan(0.03);
  }

  @Test
  void anUnreachableBrokerIsAUsageErrorThatSaysWhatToDo(@TempDir Path dir) throws IOException {
    int closedPort;
    try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      closedPort = socket.getLocalPort();
    }
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();

    int status =
        Armgals.execute(
            Catalog.of(List.of(new Distributed())),
            new PrintStream(out, true, StandardCharsets.UTF_8),
            new PrintStream(err, true, StandardCharsets.UTF_8),
            "run",
            "distributed",
            "--broker",
            "tcp://127.0.0.1:" + closedPort,
            "--out",
            dir.toString());

    String message = err.toString(StandardCharsets.UTF_8);
    assertThat(status).isEqualTo(Armgals.USAGE);
    assertThat(message.strip())
        .startsWith("armgals: could not reach the broker at tcp://127.0.0.1:" + closedPort)
        .contains("leave --broker out")
        .doesNotContain("\n");
  }

  @Test
  void atomsOutsideTwoToSixAreRefusedNamingTheValueAndTheRange(@TempDir Path dir) {
    Distributed example = new Distributed();
    for (int atoms : new int[] {1, 7}) {
      RunSettings settings = settings(dir, atoms);
      assertThatThrownBy(() -> example.scene(settings))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("--atoms " + atoms)
          .hasMessageContaining("2 to 6");
    }
  }

  private static RunSettings settings(Path dir, int atoms) {
    return new RunSettings(
        OptionalLong.empty(),
        Optional.empty(),
        Duration.ofMillis(10),
        1,
        Optional.of(atoms),
        false,
        Optional.empty(),
        dir);
  }

  private static Vec3 centre(Simulation sim) {
    double x = 0;
    double y = 0;
    double z = 0;
    for (int id : sim.atomIds()) {
      Vec3 p = sim.atom(id).sensors().position();
      x += p.x();
      y += p.y();
      z += p.z();
    }
    int n = sim.atomIds().size();
    return new Vec3(x / n, y / n, z / n);
  }
}
