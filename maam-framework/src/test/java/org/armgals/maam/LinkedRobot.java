package org.armgals.maam;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.armgals.active.TimeSource;
import org.armgals.gals.ReactiveEntity;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.FakeBody;

/**
 * A robot for the island tests. Its schema {@code link}: an inbox perceptor emits on {@link #LINK}
 * the sum of the {@link Num} payloads its entity took at the release, plus the inbox's bias; an
 * outbox actuator records that sum, commands it to the motor and sends {@code (sum × 31 + 7) mod
 * 1000} to each of the robot's peers, which take it at their next release.
 */
final class LinkedRobot extends AbstractRobot {

  static final Port<Num> LINK = Port.of("link", Num.class);

  final FakeBody fake;

  /** The entities the outbox sends to; set before the first release. */
  final List<ReactiveEntity<?>> peers = new CopyOnWriteArrayList<>();

  /** The inbox's sum of each cycle; written by the robot's cycles, read between them. */
  final List<Integer> sums = new ArrayList<>();

  private LinkedRobot(String name, FakeBody body, TimeSource time, MetaRobot meta) {
    super(name, body, time, meta);
    this.fake = body;
    Perceptor inbox = inbox(0);
    Outbox outbox = new Outbox();
    addSchema(
        Schema.builder("link").add(inbox).add(outbox).wire(inbox, LINK, outbox, LINK).build());
  }

  static LinkedRobot create(String name, TimeSource time) {
    return create(name, time, MetaRobot.create(Scheduler.topological()));
  }

  static LinkedRobot create(String name, TimeSource time, MetaRobot meta) {
    FakeBody body = FakeBody.builder(name + "-body").actuator(TestRobot.MOTOR).build();
    return new LinkedRobot(name, body, time, meta);
  }

  /** An inbox named {@code inbox}: a replacement for {@link Adaptation.ChangeModule}. */
  Perceptor inbox(int bias) {
    return new Inbox(bias);
  }

  void point(org.armgals.kernel.AdaptationPoint point) {
    setAdaptationPoint(point);
  }

  void bmeta(BMetaRobot bmeta) {
    setBehavioralMeta(bmeta);
  }

  private final class Inbox implements Perceptor {
    private final int bias;

    Inbox(int bias) {
      this.bias = bias;
    }

    @Override
    public String name() {
      return "inbox";
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(LINK);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      int sum = bias;
      for (Object in : received()) {
        sum += ((Num) in).value();
      }
      out.emit(LINK, new Num(sum));
    }
  }

  private final class Outbox implements Actuator {
    @Override
    public String name() {
      return "outbox";
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of(LINK);
    }

    @Override
    public void act(Inputs in, Body body) {
      Num link = in.get(LINK);
      int sum = link == null ? 0 : link.value();
      sums.add(sum);
      body.command(TestRobot.MOTOR, sum);
      for (ReactiveEntity<?> peer : peers) {
        emit(peer, new Num((sum * 31 + 7) % 1000));
      }
    }
  }
}
