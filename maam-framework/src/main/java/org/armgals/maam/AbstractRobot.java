package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Clock;
import org.armgals.active.ReactiveCycle;
import org.armgals.active.TimeSource;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.RobotErrorHandler;
import org.jspecify.annotations.Nullable;

/**
 * A robot (paper §5.4, step 4: the programmer's {@code Robot} extends this class and registers its
 * schemas, modules and connectors in its constructor). Each {@link #cycle} runs every behavior
 * module once in the order of the schedule its {@link MetaRobot} computed, then tells the body the
 * cycle ended, notifies the {@link BMetaRobot} if there is one, and applies the requested
 * adaptations at its {@link AdaptationPoint}.
 *
 * <p>A cycle is a method: {@link #start} runs it on a clock as a synchronous active object; tests
 * and simulators call {@link #cycle} by hand.
 *
 * <p>Threading: one thread at a time runs {@link #cycle} (the clock's release gives the
 * happens-before between two cycles). The registration methods ({@link #addSchema} and the others)
 * are for the constructor, for the thread stepping the robot between cycles, or for the robot's own
 * modules; any other thread asks through {@link #request}, which is thread-safe.
 */
public abstract class AbstractRobot {

  private final String name;
  private final Body body;
  private final TimeSource time;
  private final MetaRobot meta;
  private final ConcurrentLinkedQueue<Adaptation> requests = new ConcurrentLinkedQueue<>();
  private final Map<Connector, ConnectorState> connectorStates = new HashMap<>();
  private final List<Adaptation> applied = new ArrayList<>();
  private final List<CycleReport.Rejected> rejected = new ArrayList<>();
  private final List<String> failedModules = new ArrayList<>();
  private final Plan.Failures failures = this::moduleFailed;

  private AdaptationPoint adaptationPoint = AdaptationPoint.END_OF_CYCLE;
  private @Nullable BMetaRobot behavioralMeta;
  private RobotErrorHandler errorHandler = RobotErrorHandler.logging();
  private @Nullable Plan plan;
  private long planVersion = -1;
  private long cycles;
  private long errors;
  private long rejections;

  /**
   * A robot with an empty program, scheduled by {@link Scheduler#topological()}.
   *
   * @param name not blank
   * @param body what it senses and drives
   * @param time where it reads the time of each cycle (its clock, when it runs on one)
   */
  protected AbstractRobot(String name, Body body, TimeSource time) {
    this(name, body, time, MetaRobot.create(Scheduler.topological()));
  }

  /** A robot whose program is held by {@code meta}. */
  protected AbstractRobot(String name, Body body, TimeSource time, MetaRobot meta) {
    requireNonNull(name, "name");
    if (name.isBlank()) {
      throw new IllegalArgumentException("robot name '" + name + "': expected not blank");
    }
    this.name = name;
    this.body = requireNonNull(body, "body");
    this.time = requireNonNull(time, "time");
    this.meta = requireNonNull(meta, "meta");
  }

  /** Its name. */
  public final String name() {
    return name;
  }

  /** Its body. */
  public final Body body() {
    return body;
  }

  /** Its scheduling meta level. */
  public final MetaRobot metaRobot() {
    return meta;
  }

  /** The order its modules run in. */
  public final Schedule schedule() {
    return meta.schedule();
  }

  /** Adds {@code schema} after the others and reschedules. See {@link Adaptation.AddSchema}. */
  public final void addSchema(Schema schema) {
    meta.apply(new Adaptation.AddSchema(schema));
  }

  /** Removes a schema and its connectors and reschedules. See {@link Adaptation.RemoveSchema}. */
  public final void removeSchema(String schemaName) {
    meta.apply(new Adaptation.RemoveSchema(schemaName));
  }

  /**
   * Adds {@code module} alone in a schema of its name: modules added this way are joined by
   * connectors.
   */
  public final void addBehaviorModule(BehaviorModule module) {
    requireNonNull(module, "module");
    addSchema(Schema.builder(module.name()).add(module).build());
  }

  /** Adds a connector and reschedules. See {@link Adaptation.AddConnector}. */
  public final void addConnector(Connector connector) {
    meta.apply(new Adaptation.AddConnector(connector));
  }

  /** Removes a connector and reschedules. See {@link Adaptation.RemoveConnector}. */
  public final void removeConnector(Connector connector) {
    meta.apply(new Adaptation.RemoveConnector(connector));
  }

  /** Replaces the whole program. See {@link Adaptation.SetScheduling}. */
  public final void setScheduling(List<Schema> schemas, List<Connector> connectors) {
    meta.apply(new Adaptation.SetScheduling(schemas, connectors));
  }

  /**
   * Replaces one module by another of the same name and shape. See {@link Adaptation.ChangeModule}.
   */
  public final void changeModule(BehaviorModule replacement) {
    meta.apply(new Adaptation.ChangeModule(replacement));
  }

  /**
   * Where in the cycle requested adaptations are applied; {@link AdaptationPoint#END_OF_CYCLE} by
   * default.
   */
  public final AdaptationPoint adaptationPoint() {
    return adaptationPoint;
  }

  /** Sets where in the cycle requested adaptations are applied. */
  protected final void setAdaptationPoint(AdaptationPoint point) {
    this.adaptationPoint = requireNonNull(point, "point");
  }

  /** Sets the behavioral meta notified at the end of each cycle. */
  protected final void setBehavioralMeta(BMetaRobot behavioralMeta) {
    this.behavioralMeta = requireNonNull(behavioralMeta, "behavioralMeta");
  }

  /** Sets where failures go; {@link RobotErrorHandler#logging()} by default. */
  protected final void setErrorHandler(RobotErrorHandler errorHandler) {
    this.errorHandler = requireNonNull(errorHandler, "errorHandler");
  }

  /**
   * Asks for {@code adaptation}, applied at the next {@link AdaptationPoint}: at the beginning of
   * the next cycle, or at the end of the current or next one. Any thread; requests are applied in
   * the order they were made.
   */
  public final void request(Adaptation adaptation) {
    requests.add(requireNonNull(adaptation, "adaptation"));
  }

  /**
   * One cycle: adaptations if at the beginning, every module in schedule order, {@link
   * Body#endCycle}, the behavioral meta's notification, adaptations if at the end.
   */
  public final void cycle() {
    long number = ++cycles;
    long now = time.nanoTime();
    if (adaptationPoint == AdaptationPoint.BEGIN_OF_CYCLE) {
      adapt();
    }
    Plan current = plan();
    current.run(number, now, body, failures);
    body.endCycle();
    BMetaRobot bmeta = behavioralMeta;
    if (bmeta != null) {
      notify(
          bmeta,
          new CycleReport(
              name, number, now, current.emissions(), applied, rejected, failedModules));
    }
    applied.clear();
    rejected.clear();
    failedModules.clear();
    if (adaptationPoint == AdaptationPoint.END_OF_CYCLE) {
      adapt();
    }
  }

  /**
   * Runs this robot on {@code clock} as a synchronous object of {@code runtime}: one cycle per
   * release. Stop the returned object to stop the robot.
   */
  public final ActiveObject<ReactiveCycle> start(ActiveRuntime runtime, Clock clock) {
    requireNonNull(runtime, "runtime");
    requireNonNull(clock, "clock");
    return ActiveObjectHost.start(this, runtime, clock);
  }

  /** The cycles run so far. */
  public final long cycles() {
    return cycles;
  }

  /** The failures so far: modules' steps and the behavioral meta's notifications. */
  public final long errors() {
    return errors;
  }

  /** The adaptations rejected so far. */
  public final long rejectedAdaptations() {
    return rejections;
  }

  private void notify(BMetaRobot bmeta, CycleReport report) {
    try {
      bmeta.onCycle(report, requests::add);
    } catch (Exception e) {
      errors++;
      errorHandler.onError(name, "bmeta", e);
    }
  }

  private void adapt() {
    Adaptation next;
    while ((next = requests.poll()) != null) {
      try {
        long before = meta.version();
        meta.apply(next);
        if (next instanceof Adaptation.ChangeModule change
            && plan != null
            && planVersion == before) {
          plan.replace(change.replacement());
          planVersion = meta.version();
        }
        applied.add(next);
      } catch (IllegalArgumentException e) {
        rejections++;
        rejected.add(new CycleReport.Rejected(next, String.valueOf(e.getMessage())));
        errorHandler.onError(name, "adaptation " + next, e);
      }
    }
  }

  private Plan plan() {
    Plan current = plan;
    if (current == null || planVersion != meta.version()) {
      connectorStates.keySet().retainAll(new java.util.HashSet<>(meta.connectors()));
      current =
          new Plan(
              meta.schedule(),
              meta.schemas(),
              meta.connectors(),
              c -> connectorStates.computeIfAbsent(c, k -> new ConnectorState()));
      plan = current;
      planVersion = meta.version();
    }
    return current;
  }

  private void moduleFailed(BehaviorModule module, Exception error) {
    errors++;
    failedModules.add(module.name());
    errorHandler.onError(name, module.name(), error);
  }
}
