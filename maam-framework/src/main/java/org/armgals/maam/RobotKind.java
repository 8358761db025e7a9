package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.armgals.kernel.Adaptation;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PSpace;
import org.armgals.representation.p.PState;

/**
 * The kind of a robot in the ARM kernel (paper figure 8: {@code AbstractRobot} is an {@code Entity}
 * whose structural meta-entity describes robots): a structural meta in the procedural
 * representation whose state space is what the robots declare observable ({@link
 * AbstractRobot#observe()}: one field per observed value) and whose behaviors are
 *
 * <ul>
 *   <li>{@value #CYCLE}, one synchronous cycle: its input is the cycle's observation and the state
 *       after it is that observation, so a behavioral meta's model replays a robot's action events
 *       exactly as it integrates its state events;
 *   <li>the paper's adaptation method requests ({@value #SET_SCHEDULING}, {@value #CHANGE_MODULE},
 *       {@value #ADD_SCHEMA}, {@value #REMOVE_SCHEMA}, {@value #ADD_CONNECTOR}, {@value
 *       #REMOVE_CONNECTOR}, {@value #SET_PARAMETER}), whose reified side leaves the state as it is
 *       (the next cycle's observation shows the change: its {@code program} and {@code schemas});
 *   <li>its <em>catalog</em>: the schemas, modules and connectors the robots of the kind can be
 *       asked to run, each a behavior named {@code schema:<name>}, {@code module:<name>} or {@code
 *       connector:<name>} that builds the part for a robot from parameters.
 * </ul>
 *
 * <p>A request names its parts instead of carrying them: the requests this class makes ({@link
 * #changeModule}, {@link #addSchema}...) hold only simple values, so the same meta code adapts a
 * robot of its own runtime or of another, where code cannot travel. The robot builds the named part
 * from its kind's catalog at its adaptation point; an unknown name or unsuitable parameters refuse
 * the request, and the meta is told why. Teaching the kind a new part while its robots run is a
 * structural change through the kernel (flow 4): {@code kind.addBehavior(RobotKind.schema(...))};
 * removing one ({@code kind.deleteBehavior("schema:climb")}) removes it from every robot of the
 * kind that runs it, at the beginning of their next cycles (flow 5).
 *
 * <p>Threading: the static methods on any thread; the kind {@link Builder#define} answers is the
 * kernel's.
 */
public final class RobotKind {

  /** One cycle; its input is the cycle's observation. */
  public static final String CYCLE = "cycle";

  /**
   * Replaces the whole program by schemas and connectors of the catalog: {@link #setScheduling}.
   */
  public static final String SET_SCHEDULING = "setScheduling";

  /** Replaces a module by one of the catalog: {@link #changeModule}. */
  public static final String CHANGE_MODULE = "changeModule";

  /** Adds a schema of the catalog: {@link #addSchema}. */
  public static final String ADD_SCHEMA = "addSchema";

  /** Removes a schema: {@link #removeSchema}. */
  public static final String REMOVE_SCHEMA = "removeSchema";

  /** Adds a connector of the catalog: {@link #addConnector}. */
  public static final String ADD_CONNECTOR = "addConnector";

  /** Removes a connector of the catalog: {@link #removeConnector}. */
  public static final String REMOVE_CONNECTOR = "removeConnector";

  /** Sets a parameter of a {@link Tunable} module: {@link #setParameter}. */
  public static final String SET_PARAMETER = "setParameter";

  /** The request behaviors, in the order of the paper's list. */
  static final List<String> REQUESTS =
      List.of(
          SET_SCHEDULING,
          CHANGE_MODULE,
          ADD_SCHEMA,
          REMOVE_SCHEMA,
          ADD_CONNECTOR,
          REMOVE_CONNECTOR,
          SET_PARAMETER);

  static final String NAME = "name";
  static final String PARAMETERS = "parameters";
  static final String REASON = "reason";
  static final String SCHEMAS = "schemas";
  static final String CONNECTORS = "connectors";
  static final String MODULE = "module";
  static final String PARAMETER = "parameter";
  static final String VALUE = "value";

  private RobotKind() {}

  /**
   * What builds a part of the catalog for a robot of the kind: called on the robot's thread at its
   * adaptation point.
   *
   * @param <R> the robots of the kind
   * @param <T> the part: a {@link Schema}, a {@link BehaviorModule} or a {@link Connector}
   */
  @FunctionalInterface
  public interface Factory<R extends AbstractRobot, T> {

    /**
     * The part, named as the catalog entry, for {@code robot}.
     *
     * @throws IllegalArgumentException parameters it cannot take (use {@link Parameters}' getters:
     *     their errors name the part and the parameter)
     */
    T build(R robot, Parameters parameters);
  }

  /**
   * A builder of the kind {@code name} for robots of class {@code robots}.
   *
   * @param name the kind's name, a kernel entity name
   * @param robots the class of its robots (the catalog's factories are given robots of it)
   */
  public static <R extends AbstractRobot> Builder<R> builder(String name, Class<R> robots) {
    return new Builder<>(checkName(name, "kind"), requireNonNull(robots, "robots"));
  }

  /**
   * A kind without a catalog, whose robots observe the fields of {@code initial}: {@code
   * builder(name, AbstractRobot.class).observing(initial).define(kernel)}.
   */
  public static StructuralMeta<PState> define(Kernel kernel, String name, PState initial) {
    return builder(name, AbstractRobot.class).observing(initial).define(kernel);
  }

  /** Settings of a kind; checked by {@link #define}. Not thread-safe. */
  public static final class Builder<R extends AbstractRobot> {
    private final String name;
    private final Class<R> robots;
    private PState initial;
    private final Map<String, Behavior<PState>> catalog = new LinkedHashMap<>();

    private Builder(String name, Class<R> robots) {
      this.name = name;
      this.robots = robots;
    }

    /**
     * What its robots observe: the fields of {@code initial}, one robot's {@link
     * AbstractRobot#observation()} before its first cycle, typically.
     */
    public Builder<R> observing(PState initialObservation) {
      this.initial = requireNonNull(initialObservation, "initialObservation");
      return this;
    }

    /**
     * What its robots observe: what every robot does ({@code cycle}, {@code program}, {@code
     * schemas}, {@code errors}) and the fields of {@code own}, with their values before the first
     * cycle (their types are the fields' types). For a kind defined where no robot is, in a meta's
     * JVM.
     */
    public Builder<R> observing(Map<String, Object> own) {
      requireNonNull(own, "own");
      Map<String, Object> all = baseObservation(0, 0, List.of(), 0);
      all.putAll(own);
      this.initial = new PState(all);
      return this;
    }

    /** Adds the schema {@code schemaName} to the catalog, built by {@code factory}. */
    public Builder<R> schema(String schemaName, Factory<R, Schema> factory) {
      return add(new CatalogEntry<>(CatalogEntry.Part.SCHEMA, schemaName, robots, factory));
    }

    /** Adds the module {@code moduleName} to the catalog, built by {@code factory}. */
    public Builder<R> module(String moduleName, Factory<R, BehaviorModule> factory) {
      return add(new CatalogEntry<>(CatalogEntry.Part.MODULE, moduleName, robots, factory));
    }

    /** Adds the connector {@code connectorName} to the catalog, built by {@code factory}. */
    public Builder<R> connector(String connectorName, Factory<R, Connector> factory) {
      return add(new CatalogEntry<>(CatalogEntry.Part.CONNECTOR, connectorName, robots, factory));
    }

    private Builder<R> add(CatalogEntry<R, ?> entry) {
      if (catalog.putIfAbsent(entry.name(), entry) != null) {
        throw new IllegalArgumentException(
            "kind " + name + " has a " + entry.name() + " already; expected a new name");
      }
      return this;
    }

    /**
     * The kind, a new structural meta of {@code kernel}.
     *
     * @throws IllegalStateException no observation given
     * @throws IllegalArgumentException a blank or taken name
     */
    public StructuralMeta<PState> define(Kernel kernel) {
      requireNonNull(kernel, "kernel");
      if (initial == null) {
        throw new IllegalStateException(
            "kind " + name + ": what its robots observe is not given (observing(...))");
      }
      PSpace space = PSpace.of(initial);
      List<PMethod> methods = new ArrayList<>();
      String kind = name;
      methods.add(PMethod.of(CYCLE, (s, in) -> observed(kind, in)));
      for (String request : REQUESTS) {
        methods.add(PMethod.of(request, (s, in) -> s));
      }
      Behaviors<PState> behaviors = space.methods(methods.toArray(PMethod[]::new));
      for (Behavior<PState> entry : catalog.values()) {
        behaviors = behaviors.with(entry);
      }
      return kernel.newStructuralMeta(name, space, behaviors);
    }
  }

  /**
   * A schema of a catalog, to teach a running kind ({@code kind.addBehavior(...)}, flow 4 of the
   * paper's §3.1).
   */
  public static <R extends AbstractRobot> Behavior<PState> schema(
      String name, Class<R> robots, Factory<R, Schema> factory) {
    return new CatalogEntry<>(CatalogEntry.Part.SCHEMA, name, robots, factory);
  }

  /** A module of a catalog, to teach a running kind. */
  public static <R extends AbstractRobot> Behavior<PState> module(
      String name, Class<R> robots, Factory<R, BehaviorModule> factory) {
    return new CatalogEntry<>(CatalogEntry.Part.MODULE, name, robots, factory);
  }

  /** A connector of a catalog, to teach a running kind. */
  public static <R extends AbstractRobot> Behavior<PState> connector(
      String name, Class<R> robots, Factory<R, Connector> factory) {
    return new CatalogEntry<>(CatalogEntry.Part.CONNECTOR, name, robots, factory);
  }

  /** The behavior name of the catalog's schema {@code name}: {@code schema:<name>}. */
  public static String schemaBehavior(String name) {
    return CatalogEntry.Part.SCHEMA.behavior(name);
  }

  /**
   * {@value #CHANGE_MODULE}: replaces the module named {@code module} by the catalog's module of
   * that name built with {@code parameters} (a new stride, a new gait...); the schedule and the
   * connectors' state are kept. The replacement must be of the same kind and ports.
   */
  public static Adaptation changeModule(String module, Map<String, ?> parameters) {
    return part(CHANGE_MODULE, module, parameters);
  }

  /**
   * {@value #ADD_SCHEMA}: adds the catalog's schema {@code schema} built with {@code parameters}.
   */
  public static Adaptation addSchema(String schema, Map<String, ?> parameters) {
    return part(ADD_SCHEMA, schema, parameters);
  }

  /** {@value #REMOVE_SCHEMA}: removes the schema named {@code schema}, and its connectors. */
  public static Adaptation removeSchema(String schema) {
    return new Adaptation.ApplyBehavior(REMOVE_SCHEMA, Map.of(NAME, checkName(schema, "schema")));
  }

  /** {@value #ADD_CONNECTOR}: adds the catalog's connector {@code connector}. */
  public static Adaptation addConnector(String connector, Map<String, ?> parameters) {
    return part(ADD_CONNECTOR, connector, parameters);
  }

  /**
   * {@value #REMOVE_CONNECTOR}: removes the connector the catalog's {@code connector} builds with
   * {@code parameters}.
   */
  public static Adaptation removeConnector(String connector, Map<String, ?> parameters) {
    return part(REMOVE_CONNECTOR, connector, parameters);
  }

  /**
   * {@value #SET_SCHEDULING}: a new reactive program for a while (paper §5.1), the catalog's
   * schemas and connectors of these names, completely rescheduled.
   */
  public static Adaptation setScheduling(List<String> schemas, List<String> connectors) {
    requireNonNull(schemas, "schemas");
    requireNonNull(connectors, "connectors");
    schemas.forEach(s -> checkName(s, "schema"));
    connectors.forEach(c -> checkName(c, "connector"));
    Map<String, Object> input = new LinkedHashMap<>();
    input.put(SCHEMAS, List.copyOf(schemas));
    input.put(CONNECTORS, List.copyOf(connectors));
    return new Adaptation.ApplyBehavior(
        SET_SCHEDULING, java.util.Collections.unmodifiableMap(input));
  }

  /**
   * {@value #SET_PARAMETER}: sets {@code parameter} of the {@link Tunable} module {@code module} to
   * {@code value} (a string, a boolean or a number).
   */
  public static Adaptation setParameter(String module, String parameter, Object value) {
    requireNonNull(value, "value");
    if (!(value instanceof String || value instanceof Boolean || value instanceof Number)) {
      throw new IllegalArgumentException(
          "value of parameter '"
              + parameter
              + "' is "
              + value
              + "; expected a string, boolean or number");
    }
    return new Adaptation.ApplyBehavior(
        SET_PARAMETER,
        Map.of(
            MODULE, checkName(module, "module"),
            PARAMETER, checkName(parameter, "parameter"),
            VALUE, value));
  }

  /**
   * {@code request} with the reason the meta asks for it (what it saw), which travels with it: the
   * robot's journal, its trace and the reflective loop's pictures tell it.
   *
   * @throws IllegalArgumentException not a request of this class
   */
  public static Adaptation because(String reason, Adaptation request) {
    requireNonNull(reason, "reason");
    Map<String, Object> input = input(request);
    input.put(REASON, reason);
    return new Adaptation.ApplyBehavior(((Adaptation.ApplyBehavior) request).behavior(), input);
  }

  /** The reason {@code request} was asked for, if it says one ({@link #because}). */
  public static Optional<String> reason(Adaptation request) {
    return request instanceof Adaptation.ApplyBehavior a
            && a.input() instanceof Map<?, ?> m
            && m.get(REASON) instanceof String why
        ? Optional.of(why)
        : Optional.empty();
  }

  /**
   * {@code request} in a few words, names and values only (the same request reads the same on every
   * run): {@code "changeModule pacemaker {stride=0.3}"}.
   */
  public static String describe(Adaptation request) {
    requireNonNull(request, "request");
    if (!(request instanceof Adaptation.ApplyBehavior a) || !(a.input() instanceof Map<?, ?> m)) {
      return request.toString();
    }
    StringBuilder text = new StringBuilder(a.behavior());
    for (String key : List.of(NAME, MODULE, PARAMETER)) {
      if (m.get(key) != null) {
        text.append(' ').append(m.get(key));
      }
    }
    if (m.get(VALUE) != null) {
      text.append(" = ").append(m.get(VALUE));
    }
    if (m.get(PARAMETERS) instanceof Map<?, ?> p && !p.isEmpty()) {
      StringBuilder values = new StringBuilder();
      new java.util.TreeMap<Object, Object>(p)
          .forEach(
              (k, v) ->
                  values
                      .append(values.isEmpty() ? "" : ", ")
                      .append(k)
                      .append('=')
                      .append(brief(v)));
      text.append(" {").append(values).append('}');
    }
    if (m.get(SCHEMAS) != null) {
      text.append(' ').append(m.get(SCHEMAS)).append(' ').append(m.get(CONNECTORS));
    }
    return text.toString();
  }

  /** A number in at most four significant digits ({@code 0.30000000000000004} reads 0.3). */
  private static Object brief(Object value) {
    if (value instanceof Double || value instanceof Float) {
      double d = ((Number) value).doubleValue();
      if (Double.isFinite(d)) {
        return new java.math.BigDecimal(d)
            .round(new java.math.MathContext(4))
            .stripTrailingZeros()
            .toPlainString();
      }
    }
    return value;
  }

  private static Adaptation part(String behavior, String name, Map<String, ?> parameters) {
    requireNonNull(parameters, "parameters");
    Map<String, Object> copy = new LinkedHashMap<>();
    parameters.forEach((k, v) -> copy.put(requireNonNull(k, "parameter name"), simple(k, v)));
    Map<String, Object> input = new LinkedHashMap<>();
    input.put(NAME, checkName(name, behavior));
    input.put(PARAMETERS, java.util.Collections.unmodifiableMap(new java.util.TreeMap<>(copy)));
    return new Adaptation.ApplyBehavior(behavior, java.util.Collections.unmodifiableMap(input));
  }

  private static Object simple(String name, Object value) {
    requireNonNull(value, () -> "parameter '" + name + "'");
    if (value instanceof String || value instanceof Boolean || value instanceof Number) {
      return value;
    }
    if (value instanceof List<?> list) {
      list.forEach(v -> simple(name, v));
      return List.copyOf(list);
    }
    throw new IllegalArgumentException(
        "parameter '"
            + name
            + "' is "
            + value
            + "; expected a string, boolean, number or list of those (a request names its parts,"
            + " it carries no code)");
  }

  /** The input map of one of this class's requests, copied. */
  static Map<String, Object> input(Adaptation request) {
    requireNonNull(request, "request");
    if (request instanceof Adaptation.ApplyBehavior a
        && REQUESTS.contains(a.behavior())
        && a.input() instanceof Map<?, ?> m) {
      Map<String, Object> copy = new LinkedHashMap<>();
      m.forEach((k, v) -> copy.put(String.valueOf(k), v));
      return copy;
    }
    throw new IllegalArgumentException(
        request + " is not a robot's program request; expected one made by RobotKind");
  }

  /** What every robot observes of itself: see {@link AbstractRobot#observe()}. */
  static Map<String, Object> baseObservation(
      long cycle, long program, List<String> schemas, long errors) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("cycle", cycle);
    m.put("program", program);
    m.put("schemas", List.copyOf(schemas));
    m.put("errors", errors);
    return m;
  }

  static String checkName(String name, String what) {
    requireNonNull(name, what);
    if (name.isBlank()) {
      throw new IllegalArgumentException(what + " name '" + name + "': expected not blank");
    }
    return name;
  }

  private static PState observed(String kind, Object input) {
    if (!(input instanceof Map<?, ?> fields)) {
      throw new IllegalArgumentException(
          "the input of " + kind + "." + CYCLE + " must be the cycle's observation, was " + input);
    }
    Map<String, Object> typed = new LinkedHashMap<>();
    fields.forEach((k, v) -> typed.put(String.valueOf(k), v));
    return new PState(typed);
  }
}
