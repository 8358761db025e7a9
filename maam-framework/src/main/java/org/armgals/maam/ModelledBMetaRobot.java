package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.function.BiFunction;
import java.util.function.Consumer;
import java.util.function.Function;

/** {@link BMetaRobot#modelled}. */
final class ModelledBMetaRobot<M> implements BMetaRobot.Modelled<M> {

  private final BiFunction<? super M, CycleReport, ? extends M> integrate;
  private final Function<? super M, List<Adaptation>> decide;
  private volatile M model;

  ModelledBMetaRobot(
      M initial,
      BiFunction<? super M, CycleReport, ? extends M> integrate,
      Function<? super M, List<Adaptation>> decide) {
    this.model = initial;
    this.integrate = integrate;
    this.decide = decide;
  }

  @Override
  public void onCycle(CycleReport report, Consumer<Adaptation> requests) {
    M next = requireNonNull(integrate.apply(model, report), "model");
    model = next;
    for (Adaptation request : decide.apply(next)) {
      requests.accept(request);
    }
  }

  @Override
  public M model() {
    return model;
  }
}
