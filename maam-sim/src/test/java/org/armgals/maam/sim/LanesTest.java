package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.concurrent.atomic.AtomicReferenceArray;
import org.junit.jupiter.api.Test;

class LanesTest {

  @Test
  void visitsEveryIndexOnceAndReturnsWhenAllAreDone() {
    try (Lanes lanes = new Lanes(3, "test")) {
      for (int count : new int[] {0, 1, Lanes.MIN_PER_LANE, 3 * Lanes.MIN_PER_LANE, 1001}) {
        for (int pass = 0; pass < 50; pass++) {
          AtomicIntegerArray visits = new AtomicIntegerArray(count);
          lanes.forEach(count, visits::incrementAndGet);
          for (int i = 0; i < count; i++) {
            assertThat(visits.get(i)).as("count %d pass %d index %d", count, pass, i).isEqualTo(1);
          }
        }
      }
    }
  }

  @Test
  void spreadsALargePassOverItsThreadsInRunsOfConsecutiveIndexes() {
    int count = 3 * Lanes.MIN_PER_LANE;
    AtomicReferenceArray<Thread> by = new AtomicReferenceArray<>(count);
    try (Lanes lanes = new Lanes(3, "test")) {
      lanes.forEach(count, i -> by.set(i, Thread.currentThread()));
    }
    assertThat(by.get(0)).isSameAs(Thread.currentThread());
    assertThat(by.get(count - 1).getName()).isEqualTo("test-lane-2");
    int changes = 0;
    for (int i = 1; i < count; i++) {
      if (by.get(i) != by.get(i - 1)) {
        changes++;
      }
    }
    assertThat(changes).isEqualTo(2);
  }

  @Test
  void aSmallPassRunsOnTheCallingThread() {
    AtomicReferenceArray<Thread> by = new AtomicReferenceArray<>(10);
    try (Lanes lanes = new Lanes(2, "test")) {
      lanes.forEach(10, i -> by.set(i, Thread.currentThread()));
    }
    for (int i = 0; i < 10; i++) {
      assertThat(by.get(i)).isSameAs(Thread.currentThread());
    }
  }

  @Test
  void aFailureInAnyLaneIsThrownToTheCallerAndTheLanesGoOn() {
    int count = 2 * Lanes.MIN_PER_LANE;
    try (Lanes lanes = new Lanes(2, "test")) {
      assertThatThrownBy(
              () ->
                  lanes.forEach(
                      count,
                      i -> {
                        if (i == count - 1) {
                          throw new IllegalStateException("atom " + i + " broke");
                        }
                      }))
          .isInstanceOf(IllegalStateException.class)
          .hasMessage("atom " + (count - 1) + " broke");
      AtomicIntegerArray visits = new AtomicIntegerArray(count);
      lanes.forEach(count, visits::incrementAndGet);
      assertThat(visits.get(count - 1)).isEqualTo(1);
    }
  }

  @Test
  void aFailureInTheCallersLaneIsThrownOnlyOnceEveryLaneIsDone() {
    int count = 2 * Lanes.MIN_PER_LANE;
    AtomicIntegerArray visits = new AtomicIntegerArray(count);
    try (Lanes lanes = new Lanes(2, "test")) {
      assertThatThrownBy(
              () ->
                  lanes.forEach(
                      count,
                      i -> {
                        if (i == 0) {
                          throw new IllegalStateException("atom 0 broke");
                        }
                        visits.incrementAndGet(i);
                      }))
          .isInstanceOf(IllegalStateException.class)
          .hasMessage("atom 0 broke");
      // The other lane's half was done by the time the failure was thrown.
      for (int i = count / 2; i < count; i++) {
        assertThat(visits.get(i)).as("index %d", i).isEqualTo(1);
      }
    }
  }

  @Test
  void refusesFewerThanOneLane() {
    assertThatThrownBy(() -> new Lanes(0, "test"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("0 lanes");
  }
}
