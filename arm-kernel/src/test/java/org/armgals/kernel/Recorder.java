package org.armgals.kernel;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.kernel.spi.MetaPolicy;

/** A meta policy that records what passes the filters, then runs a reaction. */
final class Recorder implements MetaPolicy {
  final List<Notification> seen = new CopyOnWriteArrayList<>();
  private final MetaPolicy reaction;

  Recorder() {
    this(MetaPolicy.MODEL_ONLY);
  }

  Recorder(MetaPolicy reaction) {
    this.reaction = reaction;
  }

  @Override
  public void onNotification(MetaContext context, Notification notification) throws Exception {
    seen.add(notification);
    reaction.onNotification(context, notification);
  }

  <N extends Notification> List<N> of(Class<N> type) {
    return seen.stream().filter(type::isInstance).map(type::cast).toList();
  }
}
