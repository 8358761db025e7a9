package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.armgals.active.jms.Presence;
import org.armgals.active.jms.SteppedPresence;
import org.armgals.active.spi.PresenceEvent;
import org.armgals.kernel.spi.MetaPolicy;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A runtime lost or gone (issue 3, decision 0028): the kernel of another runtime hears it from its
 * presence and tells the behavioral metas that model entities living there. Both presences are
 * stepped by hand on the kernels' manual time, so a runtime falls silent exactly when the test
 * says.
 */
class RuntimeLostTest extends TwoRuntimesFixture {
  private static final Duration PERIOD = Duration.ofMillis(100);
  private static final int MISSED = 3;

  private final BlockingQueue<PresenceEvent> heardByMeta = new LinkedBlockingQueue<>();
  private SteppedPresence basePresence;
  private SteppedPresence metaPresence;

  @BeforeEach
  void presences() throws Exception {
    String prefix = broker.prefix() + "-lost";
    basePresence = SteppedPresence.start(presence(prefix, "base"));
    // The kernel's listener first: once the test hears an event, the kernel has handled it.
    metaPresence =
        SteppedPresence.start(
            presence(prefix, "meta")
                .listener(metaKernel.presenceListener())
                .listener(heardByMeta::add));
    basePresence.step();
    assertThat(next()).isEqualTo(new PresenceEvent.Joined("base"));
  }

  @AfterEach
  void closePresences() {
    basePresence.close();
    metaPresence.close();
  }

  private Presence.Builder presence(String prefix, String runtime) {
    return Presence.builder()
        .broker(broker.broker().inVmUrl())
        .prefix(prefix)
        .runtime(runtime)
        .period(PERIOD)
        .missedBeats(MISSED)
        .timeSource(time);
  }

  private PresenceEvent next() throws InterruptedException {
    PresenceEvent event = heardByMeta.poll(WAIT.toSeconds(), TimeUnit.SECONDS);
    assertThat(event).as("a presence event within %s", WAIT).isNotNull();
    return event;
  }

  @Test
  void aMetaHearsThatItsEntityIsLostWhenTheEntitysRuntimeStopsBeating() throws Exception {
    Entity robot = robot("robot", NotificationPolicy.statesOnly());
    assertThat(robot.address().runtime()).isEqualTo("base");
    Recorder watcher = new Recorder();
    BehavioralMeta meta = metaKernel.newBehavioralMeta("watcher", watcher, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    meta.setFilter(remote, "kind = 'threshold'").touch();
    long lastSeq = awaitModel(meta, remote, v -> v.lastSeq() >= 1).lastSeq();
    assertThat(meta.model(remote).getValue(WAIT).lost()).isFalse();

    time.advance(PERIOD.multipliedBy(MISSED)); // silent exactly as long as allowed: not yet lost
    metaPresence.step();
    assertThat(heardByMeta).isEmpty();
    time.advance(Duration.ofNanos(1));
    metaPresence.step();

    assertThat(next()).isInstanceOf(PresenceEvent.Lost.class);
    ModelView model = awaitModel(meta, remote, ModelView::lost);
    assertThat(model.lastSeq()).isEqualTo(lastSeq);
    assertThat(watcher.of(FailureEvent.class))
        .as("told whatever the filter")
        .singleElement()
        .satisfies(
            f -> {
              assertThat(f.entity()).isEqualTo(robot.address());
              assertThat(f.destination()).isEqualTo(meta.address());
              assertThat(f.seq()).isEqualTo(lastSeq);
              assertThat(f.error()).isEqualTo(PresenceEvent.Lost.class.getName());
              assertThat(f.message()).contains("'base'").contains("lost");
            });
    // The fixture's kernels register no MBeans; the bean is the one JMX would serve.
    BehavioralMetaMXBean jmx = new Jmx.MetaBean((BehavioralMetaImpl) meta);
    assertThat(jmx.getLost()).isEqualTo(Map.of("robot", true));
  }

  @Test
  void aLostModelIsNoLongerLostOnceItHearsFromItsEntityAgain() throws Exception {
    Entity robot = robot("robot", NotificationPolicy.statesOnly());
    BehavioralMeta meta =
        metaKernel.newBehavioralMeta("watcher", MetaPolicy.MODEL_ONLY, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    long lastSeq = awaitModel(meta, remote, v -> v.lastSeq() >= 1).lastSeq();
    time.advance(PERIOD.multipliedBy(MISSED + 1));
    metaPresence.step();
    assertThat(next()).isInstanceOf(PresenceEvent.Lost.class);
    awaitModel(meta, remote, ModelView::lost);

    robot.call("work", 0.1).getValue(); // a cut link, not a dead JVM: the robot is still there

    ModelView model = awaitModel(meta, remote, v -> v.lastSeq() > lastSeq);
    assertThat(model.lost()).isFalse();
  }

  @Test
  void aRuntimeThatLeavesIsToldAsGone() throws Exception {
    Entity robot = robot("robot", NotificationPolicy.statesOnly());
    Recorder watcher = new Recorder();
    BehavioralMeta meta = metaKernel.newBehavioralMeta("watcher", watcher, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    awaitModel(meta, remote, v -> v.lastSeq() >= 1);

    basePresence.close();

    assertThat(next()).isEqualTo(new PresenceEvent.Left("base"));
    assertThat(awaitModel(meta, remote, ModelView::lost).entity()).isEqualTo(robot.address());
    assertThat(watcher.of(FailureEvent.class))
        .singleElement()
        .satisfies(f -> assertThat(f.error()).isEqualTo(PresenceEvent.Left.class.getName()));
  }

  @Test
  void aMetaWithNoEntityInTheLostRuntimeHearsNothing() throws Exception {
    Recorder bystander = new Recorder();
    BehavioralMeta meta = metaKernel.newBehavioralMeta("bystander", bystander, Damping.none());
    Entity local =
        metaRobots.newEntity(
            "local",
            meta,
            EntityOptions.defaults().withNotification(NotificationPolicy.statesOnly()));
    awaitModel(meta, local, v -> v.lastSeq() >= 1);
    int seen = bystander.seen.size();

    time.advance(PERIOD.multipliedBy(MISSED + 1));
    metaPresence.step();
    assertThat(next()).isInstanceOf(PresenceEvent.Lost.class);

    // Ordered after whatever the kernel's listener sent this meta.
    assertThat(meta.model(local).getValue(WAIT).lost()).isFalse();
    assertThat(bystander.seen).hasSize(seen);
    assertThat(bystander.of(FailureEvent.class)).isEmpty();
  }
}
