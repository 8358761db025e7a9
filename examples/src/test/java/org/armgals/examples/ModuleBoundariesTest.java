package org.armgals.examples;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.armgals.active.ActiveContext;
import org.armgals.active.ActiveException;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ActiveRuntimeMXBean;
import org.armgals.active.Address;
import org.armgals.active.BufferFullException;
import org.armgals.active.Callable;
import org.armgals.active.Clock;
import org.armgals.active.ClockStats;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.Filter;
import org.armgals.active.Future;
import org.armgals.active.FutureEvent;
import org.armgals.active.FutureInterruptedException;
import org.armgals.active.FutureNotAvailableException;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.FutureValue;
import org.armgals.active.Guard;
import org.armgals.active.ManualClock;
import org.armgals.active.MethodRequest;
import org.armgals.active.Mode;
import org.armgals.active.ObjectConfig;
import org.armgals.active.ObjectStoppedException;
import org.armgals.active.OverflowPolicy;
import org.armgals.active.ReactiveCycle;
import org.armgals.active.RealTimeClock;
import org.armgals.active.Request;
import org.armgals.active.RequestFailedException;
import org.armgals.active.RuntimeStats;
import org.armgals.active.Selectable;
import org.armgals.active.ServantAction;
import org.armgals.active.ServantFunction;
import org.armgals.active.ShutdownMode;
import org.armgals.active.SynchronizedMethodRequest;
import org.armgals.active.SynchronousFuture;
import org.armgals.active.SynchronousFutureValue;
import org.armgals.active.TimeSource;
import org.armgals.active.TransportStats;
import org.armgals.active.WaitCycleException;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;
import org.armgals.active.jms.Presence;
import org.armgals.active.jms.Subscription;
import org.armgals.active.spi.AllowList;
import org.armgals.active.spi.BackoffIdleStrategy;
import org.armgals.active.spi.CycleRecorder;
import org.armgals.active.spi.DeadlinePacer;
import org.armgals.active.spi.ErrorHandler;
import org.armgals.active.spi.IdleStrategy;
import org.armgals.active.spi.NameService;
import org.armgals.active.spi.ObjectListener;
import org.armgals.active.spi.PresenceEvent;
import org.armgals.active.spi.PresenceListener;
import org.armgals.active.spi.RemoteAnswer;
import org.armgals.active.spi.Transport;
import org.armgals.examples.archfixture.alpha.Api;
import org.armgals.examples.archfixture.gamma.Service;
import org.armgals.examples.archfixture.gamma.spi.Plugin;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The layering rules of docs/architecture.md, over every armgals class on this module's class path
 * (examples depends on all modules but benchmarks): no module reaches another's {@code .internal}
 * package, each module exports exactly its listed API, and no module's packages form a cycle.
 */
class ModuleBoundariesTest {

  /** The root package of each module, as docs/architecture.md's module map lists them. */
  static final List<String> MODULE_ROOTS =
      List.of(
          "org.armgals.active",
          "org.armgals.representation",
          "org.armgals.kernel",
          "org.armgals.gals",
          "org.armgals.maam",
          "org.armgals.maam.sim",
          "org.armgals.testkit",
          "org.armgals.testkit.maam",
          "org.armgals.examples",
          "org.armgals.bench");

  /**
   * arm-active's public API, the JMS transport's package ({@code org.armgals.active.jms}) included:
   * adding a public type means adding it here, on purpose.
   */
  static final List<Class<?>> ACTIVE_API =
      List.of(
          ActiveContext.class,
          ActiveException.class,
          ActiveObject.class,
          ActiveRef.class,
          ActiveRuntime.class,
          ActiveRuntime.Builder.class,
          ActiveRuntimeMXBean.class,
          Address.class,
          BufferFullException.class,
          Callable.class,
          Clock.class,
          ClockStats.class,
          Event.class,
          EventProcessor.class,
          Future.class,
          Filter.class,
          FutureEvent.class,
          FutureInterruptedException.class,
          FutureNotAvailableException.class,
          FutureTimeoutException.class,
          FutureValue.class,
          Guard.class,
          ManualClock.class,
          MethodRequest.class,
          Mode.class,
          ObjectConfig.class,
          ObjectStoppedException.class,
          OverflowPolicy.class,
          OverflowPolicy.Block.class,
          OverflowPolicy.Reject.class,
          OverflowPolicy.DropNewest.class,
          OverflowPolicy.DropOldest.class,
          ReactiveCycle.class,
          RealTimeClock.class,
          Request.class,
          RequestFailedException.class,
          RuntimeStats.class,
          Selectable.class,
          ServantAction.class,
          ServantFunction.class,
          ShutdownMode.class,
          SynchronizedMethodRequest.class,
          SynchronousFuture.class,
          SynchronousFutureValue.class,
          TimeSource.class,
          TransportStats.class,
          WaitCycleException.class,
          AllowList.class,
          BackoffIdleStrategy.class,
          BackoffIdleStrategy.Phase.class,
          CycleRecorder.class,
          CycleRecorder.Figures.class,
          DeadlinePacer.class,
          ErrorHandler.class,
          IdleStrategy.class,
          NameService.class,
          ObjectListener.class,
          PresenceEvent.class,
          PresenceEvent.Joined.class,
          PresenceEvent.Left.class,
          PresenceEvent.Lost.class,
          PresenceListener.class,
          RemoteAnswer.class,
          RemoteAnswer.Receiver.class,
          Transport.class,
          Transport.Inbound.class,
          EmbeddedBroker.class,
          EmbeddedBroker.Builder.class,
          JmsTransport.class,
          JmsTransport.Builder.class,
          JmsTransport.Guarantee.class,
          JmsTransport.Topic.class,
          Presence.class,
          Presence.Builder.class,
          Subscription.class);

  private static final JavaClasses ARMGALS =
      new ClassFileImporter()
          .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
          .importPackages("org.armgals");

  private static final JavaClasses FIXTURES =
      new ClassFileImporter().importPackages("org.armgals.examples.archfixture");

  private static final List<String> FIXTURE_ROOTS =
      List.of("org.armgals.examples.archfixture.alpha", "org.armgals.examples.archfixture.beta");

  @Test
  void importSeesArmActive() {
    assertThat(ARMGALS.contain(ActiveRuntime.class)).isTrue();
    assertThat(ARMGALS.stream().anyMatch(c -> c.getSimpleName().equals("Core"))).isTrue();
  }

  @Test
  void noModuleReachesAnotherModulesInternalPackage() {
    ModuleRules.internalPackagesStayInTheirModule(MODULE_ROOTS).check(ARMGALS);
  }

  /**
   * The core of arm-active ({@code org.armgals.active} and its {@code .spi}) names no class of the
   * JMS transport, of Jakarta Messaging or of Artemis but its selector library (the filters' own
   * semantics, decision 0058), so that a user in one JVM needs none of them.
   */
  @Test
  void armActivesCoreNamesNoTransportClass() {
    ModuleRules.coreNamesNoTransportClass().check(ARMGALS);
  }

  @Test
  void armActiveExportsOnlyItsApi() {
    ModuleRules.onlyTheApiIsPublic("org.armgals.active", ACTIVE_API).check(ARMGALS);
  }

  /** The other modules' API lists, in {@code src/test/resources/api/<module>.txt}. */
  @ParameterizedTest(name = "{0} exports only its API")
  @CsvSource({
    "arm-representation, org.armgals.representation",
    "arm-kernel, org.armgals.kernel",
    "arm-gals, org.armgals.gals",
    "maam-framework, org.armgals.maam",
    "maam-sim, org.armgals.maam.sim",
    "armgals-testkit, org.armgals.testkit",
    "armgals-testkit-maam, org.armgals.testkit.maam"
  })
  void eachModuleExportsOnlyItsListedApi(String module, String root) throws IOException {
    Set<String> api = apiList(module);
    assertThat(api).as("the API list of %s", module).isNotEmpty();
    assertThat(api)
        .as("every listed type of %s exists", module)
        .allSatisfy(name -> assertThat(ARMGALS.contain(name)).as(name).isTrue());
    List<String> nested = MODULE_ROOTS.stream().filter(r -> r.startsWith(root + ".")).toList();
    ModuleRules.onlyTheApiIsPublic(root, api, nested).check(ARMGALS);
  }

  /**
   * Every library module's packages are free of cycles. The benchmarks are not on this class path
   * (no tests run in that module); examples has a test of its own below.
   */
  @ParameterizedTest(name = "no package cycle in {0}")
  @ValueSource(
      strings = {
        "org.armgals.active",
        "org.armgals.representation",
        "org.armgals.kernel",
        "org.armgals.gals",
        "org.armgals.maam",
        "org.armgals.maam.sim",
        "org.armgals.testkit",
        "org.armgals.testkit.maam"
      })
  void noModulesPackagesFormACycle(String root) {
    List<String> nested = MODULE_ROOTS.stream().filter(r -> r.startsWith(root + ".")).toList();
    ModuleRules.noPackageCycles(root, nested).check(ARMGALS);
  }

  @Test
  void examplesPackagesFormNoCycle() {
    // The run machinery (org.armgals.examples.run) sits apart from the command line, so that the
    // robots and the simulation glue that use it do not import the command line back.
    ModuleRules.noPackageCycles("org.armgals.examples", List.of()).check(ARMGALS);
  }

  @Test
  void cycleRuleReportsACycleBetweenTwoPackages() {
    assertThatThrownBy(
            () ->
                ModuleRules.noPackageCycles("org.armgals.examples.archfixture.gamma", List.of())
                    .check(FIXTURES))
        .isInstanceOf(AssertionError.class)
        .hasMessageContaining("gamma.left.Left")
        .hasMessageContaining("gamma.right.Right")
        .hasMessageNotContaining("Plugin");
  }

  @Test
  void cycleRuleLetsAModulesApiAndSpiReferToEachOther() {
    ModuleRules.noPackageCycles("org.armgals.examples.archfixture.gamma", List.of())
        .check(new ClassFileImporter().importClasses(Service.class, Plugin.class));
  }

  @Test
  void cycleRuleLeavesOutTheModulesNestedInIt() {
    ModuleRules.noPackageCycles(
            "org.armgals.examples.archfixture.gamma",
            List.of("org.armgals.examples.archfixture.gamma.left"))
        .check(FIXTURES);
  }

  private static Set<String> apiList(String module) throws IOException {
    try (InputStream in =
        ModuleBoundariesTest.class.getResourceAsStream("/api/" + module + ".txt")) {
      if (in == null) {
        throw new IllegalStateException("no API list for " + module);
      }
      return new String(in.readAllBytes(), StandardCharsets.UTF_8)
          .lines()
          .map(String::strip)
          .filter(l -> !l.isEmpty() && !l.startsWith("#"))
          .collect(Collectors.toCollection(TreeSet::new));
    }
  }

  @Test
  void internalRuleReportsAReachIntoAnotherModulesInternals() {
    assertThatThrownBy(
            () -> ModuleRules.internalPackagesStayInTheirModule(FIXTURE_ROOTS).check(FIXTURES))
        .isInstanceOf(AssertionError.class)
        .hasMessageContaining("beta.Leak")
        .hasMessageContaining("alpha.internal.Secret")
        .hasMessageNotContaining("alpha.Api.");
  }

  @Test
  void internalRuleLetsAModuleUseItsOwnInternals() {
    ModuleRules.internalPackagesStayInTheirModule(FIXTURE_ROOTS)
        .check(new ClassFileImporter().importClasses(Api.class));
  }

  @Test
  void apiRuleReportsAPublicClassOutsideTheList() {
    assertThatThrownBy(
            () ->
                ModuleRules.onlyTheApiIsPublic(
                        "org.armgals.examples.archfixture.alpha", List.of(Api.class))
                    .check(FIXTURES))
        .isInstanceOf(AssertionError.class)
        .hasMessageContaining("alpha.Exposed")
        .hasMessageNotContaining("alpha.Api>");
  }

  @Test
  void moduleOfPicksTheLongestRoot() {
    assertThat(ModuleRules.moduleOf("org.armgals.maam.sim.internal", MODULE_ROOTS))
        .isEqualTo("org.armgals.maam.sim");
    assertThat(ModuleRules.moduleOf("org.armgals.maam.internal", MODULE_ROOTS))
        .isEqualTo("org.armgals.maam");
    assertThat(ModuleRules.moduleOf("org.armgalsx", MODULE_ROOTS)).isNull();
  }
}
