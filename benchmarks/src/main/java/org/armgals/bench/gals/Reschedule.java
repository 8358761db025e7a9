package org.armgals.bench.gals;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.armgals.active.TimeSource;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.BehaviorModule;
import org.armgals.maam.Connector;
import org.armgals.maam.Derivator;
import org.armgals.maam.Inhibitor;
import org.armgals.maam.MetaRobot;
import org.armgals.maam.PortRef;
import org.armgals.maam.Schema;
import org.armgals.testkit.maam.FakeBody;

/**
 * {@code gals name=reschedule modules=<n> ms=<x>}: the time of one complete rescheduling of a robot
 * of {@code n} modules, as its {@link MetaRobot} does it when a schema is added or removed (check,
 * merge of the partial schedules, new schedule). Schemas of 10 modules in chains with side wires,
 * one connector per schema to a later schema. The median of alternating add/remove of one schema.
 */
final class Reschedule {

  private static final int PER_SCHEMA = 10;

  private Reschedule() {}

  static void run() {
    TimeSource time = TimeSource.system();
    for (int n : new int[] {1_000, 10_000, 100_000}) {
      AbstractRobot robot =
          new AbstractRobot("bench", FakeBody.builder("bench-body").build(), time) {};
      MetaRobot meta = robot.metaRobot();
      Random random = new Random(n);
      List<Schema> schemas = new ArrayList<>();
      for (int s = 0; s < n / PER_SCHEMA - 1; s++) {
        schemas.add(schema("s" + s, random));
      }
      List<Connector> connectors = new ArrayList<>();
      java.util.Set<PortRef> fedSides = new java.util.HashSet<>();
      for (int s = 0; s + 1 < schemas.size(); s++) {
        Schema from = schemas.get(s);
        Schema to = schemas.get(s + 1 + random.nextInt(Math.min(5, schemas.size() - s - 1)));
        BehaviorModule source = from.modules().get(random.nextInt(PER_SCHEMA - 1));
        BehaviorModule target = to.modules().get(1 + random.nextInt(PER_SCHEMA - 2));
        PortRef side = PortRef.of(target, BenchModules.SIDE);
        boolean sideFree =
            !target.name().endsWith(".gain5")
                && !target.name().endsWith(".gain7")
                && fedSides.add(side);
        connectors.add(
            sideFree
                ? new Derivator(
                    PortRef.of(source, BenchModules.OUT), PortRef.of(target, BenchModules.SIDE))
                : new Inhibitor(
                    PortRef.of(source, BenchModules.OUT),
                    PortRef.of(target, BenchModules.IN),
                    Duration.ofMillis(20)));
      }
      robot.setScheduling(schemas, connectors);
      Schema extra = schema("extra", random);
      int rounds = n >= 100_000 ? 10 : n >= 10_000 ? 50 : 400;
      long[] nanos = new long[2 * rounds];
      java.lang.management.ThreadMXBean threads =
          java.lang.management.ManagementFactory.getThreadMXBean();
      long cpuStart = 0;
      for (int r = 0; r < rounds; r++) {
        if (r == rounds / 2) {
          cpuStart = threads.getCurrentThreadCpuTime();
        }
        long start = time.nanoTime();
        robot.addSchema(extra);
        long added = time.nanoTime();
        robot.removeSchema("extra");
        nanos[2 * r] = added - start;
        nanos[2 * r + 1] = time.nanoTime() - added;
      }
      double cpuMs = (threads.getCurrentThreadCpuTime() - cpuStart) / 1e6 / rounds;
      // The first half warms up; the median of the second half is the figure.
      long[] measured = Arrays.copyOfRange(nanos, rounds, 2 * rounds);
      Arrays.sort(measured);
      double ms = measured[measured.length / 2] / 1e6;
      if (meta.schedule().modules().size() != schemas.size() * PER_SCHEMA) {
        throw new IllegalStateException("lost modules: " + meta.schedule().modules().size());
      }
      System.err.printf(
          "# reschedule: %d modules, %.3f ms of this thread's CPU time per rescheduling%n",
          n, cpuMs);
      System.out.printf("gals name=reschedule modules=%d ms=%.3f%n", n, ms);
    }
  }

  /** A chain of a perceptor, eight reactors and an actuator, with two side wires. */
  private static Schema schema(String name, Random random) {
    List<BehaviorModule> chain = new ArrayList<>();
    chain.add(new BenchModules.Sense(name + ".sense"));
    for (int i = 1; i < PER_SCHEMA - 1; i++) {
      chain.add(new BenchModules.Gain(name + ".gain" + i, 0.5 + random.nextDouble()));
    }
    chain.add(new BenchModules.Drive(name + ".drive"));
    Schema.Builder builder = Schema.builder(name);
    chain.forEach(builder::add);
    for (int i = 0; i + 1 < chain.size(); i++) {
      builder.wire(chain.get(i), BenchModules.OUT, chain.get(i + 1), BenchModules.IN);
    }
    builder.wire(chain.get(1), BenchModules.OUT, chain.get(5), BenchModules.SIDE);
    builder.wire(chain.get(2), BenchModules.OUT, chain.get(7), BenchModules.SIDE);
    return builder.build();
  }
}
