package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;

/** Filters change at run time with no notification lost or judged twice. */
class FilterSwapTest extends KernelFixture {
  static final String BEFORE = "behavior = 'normal'";
  static final String AFTER = "kind = 'action'";

  record Judged(long seq, String filter) {}

  @Test
  void swappingAFilterWhileNotificationsFlowLosesAndDuplicatesNone() throws Exception {
    List<Judged> judged = new CopyOnWriteArrayList<>();
    CountDownLatch underBefore = new CountDownLatch(200);
    CountDownLatch underAfter = new CountDownLatch(200);
    BehavioralMeta meta =
        kernel.newBehavioralMeta(
            "meta",
            (ctx, n) -> {
              if (n instanceof ActionEvent a) {
                String filter = ctx.model(a.entity()).filter();
                judged.add(new Judged(a.seq(), filter));
                (filter.equals(BEFORE) ? underBefore : underAfter).countDown();
              }
            },
            Damping.none());
    Entity robot =
        robotKind()
            .newEntity(
                "robot",
                meta,
                EntityOptions.defaults().withNotification(NotificationPolicy.actionsOnly()));
    meta.setFilter(robot, BEFORE).touch();

    AtomicBoolean stop = new AtomicBoolean();
    Thread sender =
        Thread.ofVirtual()
            .start(
                () -> {
                  while (!stop.get()) {
                    robot.call("normal", null).getValue(); // keeps the queues short
                  }
                });
    assertThat(underBefore.await(30, TimeUnit.SECONDS)).isTrue();
    meta.setFilter(robot, AFTER).touch();
    assertThat(underAfter.await(30, TimeUnit.SECONDS)).isTrue();
    stop.set(true);
    sender.join();
    drain(robot);
    drain(meta);

    long last = meta.model(robot).getValue().lastSeq();
    assertThat(judged)
        .extracting(Judged::seq)
        .containsExactlyElementsOf(LongStream.rangeClosed(2, last).boxed().toList());
    int swap =
        judged.indexOf(judged.stream().filter(j -> j.filter().equals(AFTER)).findFirst().get());
    assertThat(judged.subList(0, swap)).allMatch(j -> j.filter().equals(BEFORE));
    assertThat(judged.subList(swap, judged.size())).allMatch(j -> j.filter().equals(AFTER));
  }

  @Test
  void aNotificationTheFilterRejectsStillUpdatesTheModel() {
    Recorder policy = new Recorder();
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity robot = robotKind().newEntity("robot", meta);
    meta.setFilter(robot, "kind = 'threshold'").touch();
    int before = policy.seen.size();

    robot.call("work", 0.5).getValue();
    drain(meta);

    assertThat(policy.seen).hasSize(before);
    assertThat(meta.model(robot).getValue().state()).isEqualTo(robot.state());
  }

  @Test
  void aSelectorThatDoesNotParseIsRefusedWithTheSelector() {
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity robot = robotKind().newEntity("robot", meta);

    assertThatThrownBy(() -> meta.setFilter(robot, "kind = = 'state'"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("kind = = 'state'");
  }
}
