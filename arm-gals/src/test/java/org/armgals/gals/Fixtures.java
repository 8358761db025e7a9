package org.armgals.gals;

import org.armgals.active.ActiveRuntime;

/** What the tests share. */
final class Fixtures {
  private Fixtures() {}

  static ActiveRuntime runtime(String name, int workers) {
    return ActiveRuntime.builder().name(name).workers(workers).jmx(false).build();
  }
}
