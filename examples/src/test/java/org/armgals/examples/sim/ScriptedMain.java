package org.armgals.examples.sim;

import java.util.List;
import org.armgals.examples.cli.Armgals;
import org.armgals.examples.cli.Catalog;

/** The armgals command line over {@link ScriptedExample} alone, for tests that run it in a JVM. */
public final class ScriptedMain {
  private ScriptedMain() {}

  /** As {@link Armgals#main}, with the scripted example as the catalog. */
  public static void main(String[] args) {
    System.exit(
        Armgals.execute(Catalog.of(List.of(new ScriptedExample())), System.out, System.err, args));
  }
}
