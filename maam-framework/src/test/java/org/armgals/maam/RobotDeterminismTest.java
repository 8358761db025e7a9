package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The same program, the same inputs: the same signals each cycle, run after run. */
class RobotDeterminismTest {

  @Test
  void aRandomProgramGivesTheSameSignalsEveryRun() {
    for (long seed = 0; seed < 200; seed++) {
      List<String> first = run(seed);
      assertThat(first).as("seed %d: signals flowed", seed).anyMatch(line -> line.contains("Num["));
      assertThat(run(seed)).as("seed %d", seed).isEqualTo(first);
    }
  }

  private static List<String> run(long seed) {
    RandomProgram program = new RandomProgram(seed, 4, 8);
    TestRobot.TestTime time = new TestRobot.TestTime();
    List<String> trace = new ArrayList<>();
    AbstractRobot robot = new AbstractRobot("r" + seed, TestBody.empty("b"), time) {};
    robot.setScheduling(program.schemas, program.connectors);
    for (int cycle = 0; cycle < 5; cycle++) {
      robot.cycle();
      trace.add(robot.cycles() + " " + robot.emissions());
      time.now += TestRobot.PERIOD;
    }
    trace.add(robot.schedule().names().toString());
    return trace;
  }
}
