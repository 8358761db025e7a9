package org.armgals.examples;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.Dependency;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaModifier;
import com.tngtech.archunit.lang.ArchCondition;
import com.tngtech.archunit.lang.ArchRule;
import com.tngtech.archunit.lang.ConditionEvents;
import com.tngtech.archunit.lang.SimpleConditionEvent;
import com.tngtech.archunit.library.dependencies.SliceAssignment;
import com.tngtech.archunit.library.dependencies.SliceIdentifier;
import com.tngtech.archunit.library.dependencies.SliceRule;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.jspecify.annotations.Nullable;

/**
 * The ArchUnit rules behind the layering rules of docs/architecture.md, parameterized so they can
 * be tested.
 */
final class ModuleRules {
  private ModuleRules() {}

  /**
   * No class reaches the {@code .internal} package of another module. A class belongs to the module
   * whose root package is the longest prefix of its own ({@code org.armgals.maam.sim.X} to
   * maam-sim, not maam-framework).
   */
  static ArchRule internalPackagesStayInTheirModule(List<String> moduleRoots) {
    return classes()
        .should(notReachAnotherModulesInternals(moduleRoots))
        .because(
            "docs/architecture.md, layering rule 2: .internal holds the rest and is never reached"
                + " from another module");
  }

  /**
   * In {@code rootPackage} and its subpackages except {@code .internal}, every public class is one
   * of {@code api}; all others stay package-private (docs/architecture.md, layering rule 3: export
   * little).
   */
  static ArchRule onlyTheApiIsPublic(String rootPackage, Collection<Class<?>> api) {
    return onlyTheApiIsPublic(
        rootPackage, api.stream().map(Class::getName).collect(Collectors.toSet()), List.of());
  }

  /**
   * As {@link #onlyTheApiIsPublic(String, Collection)}, with the API given by binary class names,
   * leaving out the packages of other modules nested in this one ({@code org.armgals.maam.sim} in
   * {@code org.armgals.maam}).
   */
  static ArchRule onlyTheApiIsPublic(
      String rootPackage, Set<String> names, List<String> nestedModuleRoots) {
    DescribedPredicate<JavaClass> nested =
        DescribedPredicate.describe(
            "in a nested module " + nestedModuleRoots,
            c ->
                nestedModuleRoots.stream()
                    .anyMatch(
                        r ->
                            c.getPackageName().equals(r)
                                || c.getPackageName().startsWith(r + ".")));
    DescribedPredicate<JavaClass> inApi =
        DescribedPredicate.describe("in the public API list", c -> names.contains(c.getName()));
    return classes()
        .that()
        .resideInAPackage(rootPackage + "..")
        .and()
        .resideOutsideOfPackage("..internal..")
        .and(DescribedPredicate.not(inApi))
        .and(DescribedPredicate.not(nested))
        .should()
        .notHaveModifier(JavaModifier.PUBLIC)
        .because(
            "docs/architecture.md, layering rule 3: implementations are package-private; the API"
                + " list is deliberate")
        .allowEmptyShould(true);
  }

  /**
   * No cycle among the packages of the module rooted at {@code root}, leaving out the packages of
   * other modules nested in it. The root package and its {@code .spi} count as one: the API takes
   * the plug-ins (a builder's {@code transport(Transport)}) and the plug-ins take the API's values
   * (a {@code Transport} sends {@code Event}s to {@code Address}es), by design.
   */
  static SliceRule noPackageCycles(String root, List<String> nestedModuleRoots) {
    SliceAssignment packages =
        new SliceAssignment() {
          @Override
          public SliceIdentifier getIdentifierOf(JavaClass c) {
            String pkg = c.getPackageName();
            if (!inPackage(pkg, root)
                || nestedModuleRoots.stream().anyMatch(r -> inPackage(pkg, r))) {
              return SliceIdentifier.ignore();
            }
            return SliceIdentifier.of(pkg.equals(root + ".spi") ? root : pkg);
          }

          @Override
          public String getDescription() {
            return "the packages of " + root + " (" + root + ".spi counted with " + root + ")";
          }
        };
    return slices()
        .assignedFrom(packages)
        .should()
        .beFreeOfCycles()
        .because("docs/architecture.md, layering rule 4: the packages of a module form no cycle");
  }

  /**
   * No class of arm-active's core ({@code org.armgals.active} and {@code org.armgals.active.spi})
   * depends on the JMS transport's package, on Jakarta Messaging or on Artemis, but for Artemis's
   * selector library and the {@code SimpleString} its filters take (docs/decisions/0058).
   */
  static ArchRule coreNamesNoTransportClass() {
    return noClasses()
        .that()
        .resideInAnyPackage("org.armgals.active", "org.armgals.active.spi")
        .should()
        .dependOnClassesThat(
            DescribedPredicate.describe(
                "are of the JMS transport, Jakarta Messaging or Artemis (but its selector)",
                (JavaClass c) -> {
                  String n = c.getName();
                  return n.startsWith("org.armgals.active.jms.")
                      || n.startsWith("jakarta.jms.")
                      || (n.startsWith("org.apache.activemq.")
                          && !n.startsWith("org.apache.activemq.artemis.selector.")
                          && !n.equals("org.apache.activemq.artemis.api.core.SimpleString"));
                }))
        .because("docs/decisions/0058: an in-JVM user of arm-active gets no broker");
  }

  private static boolean inPackage(String pkg, String root) {
    return pkg.equals(root) || pkg.startsWith(root + ".");
  }

  private static ArchCondition<JavaClass> notReachAnotherModulesInternals(List<String> roots) {
    return new ArchCondition<>("not reach the .internal package of another module") {
      @Override
      public void check(JavaClass source, ConditionEvents events) {
        String from = moduleOf(source.getPackageName(), roots);
        for (Dependency d : source.getDirectDependenciesFromSelf()) {
          String target = d.getTargetClass().getBaseComponentType().getPackageName();
          if (!isInternal(target)) {
            continue;
          }
          String to = moduleOf(target, roots);
          if (to != null && !to.equals(from)) {
            events.add(
                SimpleConditionEvent.violated(
                    d,
                    "module " + from + " reaches " + to + "'s internals: " + d.getDescription()));
          }
        }
      }
    };
  }

  static boolean isInternal(String pkg) {
    return pkg.endsWith(".internal") || pkg.contains(".internal.");
  }

  /** The longest module root that {@code pkg} lies in, or null outside every module. */
  static @Nullable String moduleOf(String pkg, List<String> roots) {
    String best = null;
    for (String r : roots) {
      if ((pkg.equals(r) || pkg.startsWith(r + "."))
          && (best == null || r.length() > best.length())) {
        best = r;
      }
    }
    return best;
  }
}
