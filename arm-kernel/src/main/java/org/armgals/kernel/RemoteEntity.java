package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.Optional;
import java.util.Set;
import org.armgals.active.ActiveContext;
import org.armgals.active.Address;
import org.armgals.active.FutureValue;
import org.armgals.representation.State;
import org.jspecify.annotations.Nullable;

/**
 * A handle on an entity of another runtime's kernel (decision 0024), made by {@link
 * Kernel#remoteEntity}: a behavioral meta of this kernel can take it as a base entity, model it
 * with a structural meta of this kernel that describes the same kind, filter and adapt it. Stimuli,
 * calls, adaptation and resynchronization requests travel to it through the runtime's transport;
 * its notifications come back on {@code arm/BMeta}.
 *
 * <p>Its state, notification policy and applied version are asked of it over the transport (a
 * blocking request, failing at the transport's reply timeout). Threading: any thread.
 */
final class RemoteEntity implements Entity {
  private final KernelImpl kernel;
  private final String name;
  private final Address address;
  private final StructuralMetaImpl<?> kind;
  private volatile @Nullable BehavioralMetaImpl meta;

  RemoteEntity(KernelImpl kernel, String name, Address address, StructuralMetaImpl<?> kind) {
    this.kernel = requireNonNull(kernel, "kernel");
    this.name = requireNonNull(name, "name");
    this.address = requireNonNull(address, "address");
    this.kind = requireNonNull(kind, "kind");
  }

  KernelImpl kernel() {
    return kernel;
  }

  StructuralMetaImpl<?> kind() {
    return kind;
  }

  /** Set by the meta of this kernel that takes it or lets it go. */
  void meta(@Nullable BehavioralMetaImpl next) {
    this.meta = next;
  }

  @Override
  public String name() {
    return name;
  }

  @Override
  public Address address() {
    return address;
  }

  @Override
  public StructuralMeta<?> structuralMeta() {
    return kind;
  }

  /** The meta of this kernel that took it, if any (a meta of another runtime is not seen). */
  @Override
  public Optional<BehavioralMeta> behavioralMeta() {
    return Optional.ofNullable(meta);
  }

  /**
   * Its state as it reports it, mapped into the space of {@link #structuralMeta()}.
   *
   * @throws IllegalStateException the report matches no single state of that space
   */
  @Override
  public State state() {
    Wire.Report r = report();
    Set<? extends State> found = kind.mapToState(r.observation(), null);
    if (found.size() != 1) {
      throw new IllegalStateException(
          "remote entity '"
              + name
              + "' reports "
              + r.observation()
              + ", which is "
              + found.size()
              + " states of "
              + kind.name()
              + "; expected exactly one");
    }
    return found.iterator().next();
  }

  @Override
  public NotificationPolicy notificationPolicy() {
    return report().policy();
  }

  @Override
  public long appliedVersion() {
    return report().appliedVersion();
  }

  private Wire.Report report() {
    return kernel.runtime().<Object>ref(address).ask(new Wire.Inspect(self(), address)).getValue();
  }

  @Override
  public void send(String trigger, @Nullable Object input) {
    requireNonNull(trigger, "trigger");
    kernel.runtime().ref(address).send(new Stimulus(self(), address, trigger, input));
  }

  @Override
  public FutureValue<@Nullable Object> call(String behavior, @Nullable Object input) {
    requireNonNull(behavior, "behavior");
    return kernel.runtime().ref(address).ask(new Wire.Call(self(), address, behavior, input));
  }

  /**
   * Always false: the end of an entity of another runtime is not seen through its handle (its
   * meta's model goes stale, {@link ModelView#staleness()}).
   */
  @Override
  public boolean isStopped() {
    return false;
  }

  @Override
  public int queueDepth() {
    return -1;
  }

  private static @Nullable Address self() {
    return ActiveContext.current().map(o -> o.address()).orElse(null);
  }

  @Override
  public String toString() {
    return name + "@" + address + " (remote)";
  }
}
