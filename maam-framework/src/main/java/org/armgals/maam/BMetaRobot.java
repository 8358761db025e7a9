package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.active.Address;
import org.armgals.active.Future;
import org.armgals.active.FutureValue;
import org.armgals.kernel.ActionEvent;
import org.armgals.kernel.Adaptation;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.ModelView;
import org.armgals.kernel.Notification;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StateEvent;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.representation.State;
import org.jspecify.annotations.Nullable;

/**
 * A behavioral meta-entity of robots (paper figure 8: {@code bmrobot1}, {@code bmrobot2}; §5.4's
 * adaptation protocol): the programmer's deliberative level extends this class and writes {@link
 * #onNotification}. {@link #start} makes it a behavioral meta-entity of the ARM kernel, an active
 * object in the asynchronous mode whose policy is this object: it never runs on a robot's thread.
 * From then on it is that meta-entity ({@link BehavioralMeta}, by forwarding), and a robot started
 * with it as its meta notifies it at each cycle:
 *
 * <ol>
 *   <li>the robot's notifications (state and action events, thresholds, failures), numbered, as its
 *       notification policy says, pass this meta's filter for the robot (a JMS selector, {@link
 *       #setFilter}, which the policy may change while the robot runs: connection and detachment);
 *   <li>the kernel integrates each into its model of the robot ({@link #model}: a gap in the
 *       numbers makes it ask for a fresh state), then calls {@link #onNotification} with what
 *       passed the filter;
 *   <li>the policy may ask for adaptations with {@link org.armgals.kernel.spi.MetaContext#adapt}
 *       and the requests of {@link RobotKind} ({@code setScheduling}, {@code changeModule}, adding
 *       and removing schemas, setting parameters), versioned, held back by its {@link Damping} when
 *       they come too often, applied by the robot at its island's adaptation point and
 *       acknowledged.
 * </ol>
 *
 * <p>The same code runs in the robot's JVM or in another: there it takes a handle on the robot
 * ({@link Kernel#lookupRemote}) with {@link #addBaseLevelEntity}, and the notifications and
 * requests travel over the broker. While it handles a notification its time is the robot's ({@link
 * org.armgals.kernel.spi.MetaContext#nanoTime()}), so its damping holds wherever it runs.
 *
 * <p>Threading: {@link #onNotification} and {@link #onInstant} on the meta-entity's own object, one
 * at a time; they must not block. The {@link BehavioralMeta} methods on any thread once started.
 */
public abstract class BMetaRobot implements BehavioralMeta, MetaPolicy {
  private final String name;
  private final Damping damping;
  private volatile @Nullable BehavioralMeta entity;

  /**
   * A meta level named {@code name} (its meta-entity's name in the kernel), adapting each robot at
   * most as {@code damping} lets it.
   */
  protected BMetaRobot(String name, Damping damping) {
    this.name = RobotKind.checkName(name, "meta");
    this.damping = requireNonNull(damping, "damping");
  }

  /**
   * Makes this meta level a behavioral meta-entity of {@code kernel} whose policy it is.
   *
   * @return this, started
   * @throws IllegalStateException already started
   * @throws IllegalArgumentException the kernel has an entity of its name
   */
  public final BMetaRobot start(Kernel kernel) {
    requireNonNull(kernel, "kernel");
    synchronized (this) {
      if (entity != null) {
        throw new IllegalStateException("meta " + name + " already runs");
      }
      entity = kernel.newBehavioralMeta(name, this, damping);
    }
    return this;
  }

  /**
   * The observation a robot's notification carries: a state event's, or the input of its {@value
   * RobotKind#CYCLE} action; empty for other notifications.
   */
  protected static Optional<Map<String, Object>> observation(Notification notification) {
    return switch (notification) {
      case StateEvent s -> Optional.of(s.observation());
      case ActionEvent a
          when RobotKind.CYCLE.equals(a.behavior()) && a.input() instanceof Map<?, ?> m ->
          Optional.of(stringKeyed(m));
      default -> Optional.empty();
    };
  }

  private static Map<String, Object> stringKeyed(Map<?, ?> m) {
    Map<String, Object> copy = new java.util.LinkedHashMap<>();
    m.forEach((k, v) -> copy.put(String.valueOf(k), v));
    return copy;
  }

  /** The damping of its adaptations. */
  public final Damping damping() {
    return damping;
  }

  private BehavioralMeta meta() {
    BehavioralMeta m = entity;
    if (m == null) {
      throw new IllegalStateException(
          "meta " + name + " is not started: make it a meta-entity with start(kernel)");
    }
    return m;
  }

  /**
   * The kernel meta-entity this meta level is, once started.
   *
   * @throws IllegalStateException not started
   */
  @Override
  public final Entity handle() {
    return meta();
  }

  @Override
  public final String name() {
    return name;
  }

  @Override
  public final Future addBaseLevelEntity(Entity base) {
    return meta().addBaseLevelEntity(base);
  }

  @Override
  public final Future deleteBaseLevelEntity(Entity base) {
    return meta().deleteBaseLevelEntity(base);
  }

  @Override
  public final List<Entity> baseLevelEntities() {
    return meta().baseLevelEntities();
  }

  @Override
  public final Future setFilter(Entity base, String selector) {
    return meta().setFilter(base, selector);
  }

  @Override
  public final FutureValue<ModelView> model(Entity base) {
    return meta().model(base);
  }

  @Override
  public final FutureValue<OptionalLong> adapt(Entity base, Adaptation adaptation) {
    return meta().adapt(base, adaptation);
  }

  @Override
  public final Address address() {
    return meta().address();
  }

  @Override
  public final StructuralMeta<?> structuralMeta() {
    return meta().structuralMeta();
  }

  @Override
  public final Optional<BehavioralMeta> behavioralMeta() {
    return meta().behavioralMeta();
  }

  @Override
  public final State state() {
    return meta().state();
  }

  @Override
  public final NotificationPolicy notificationPolicy() {
    return meta().notificationPolicy();
  }

  @Override
  public final long appliedVersion() {
    return meta().appliedVersion();
  }

  @Override
  public final void send(String trigger, @Nullable Object input) {
    meta().send(trigger, input);
  }

  @Override
  public final FutureValue<@Nullable Object> call(String behavior, @Nullable Object input) {
    return meta().call(behavior, input);
  }

  @Override
  public final boolean isStopped() {
    BehavioralMeta m = entity;
    return m != null && m.isStopped();
  }

  @Override
  public final int queueDepth() {
    return meta().queueDepth();
  }

  @Override
  public String toString() {
    BehavioralMeta m = entity;
    return "meta " + name + (m == null ? "" : " (" + m.address() + ")");
  }
}
