package org.armgals.testkit;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Inherited;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * A test that takes an {@link org.armgals.active.ActiveRuntime} as a parameter: {@link
 * ActiveRuntimeExtension} gives each test method (and its {@code @BeforeEach} and {@code AfterEach}
 * methods) a runtime of its own and shuts it down after the test. On a method, the annotation's
 * settings replace the class's.
 *
 * <p>With {@link #manualClock()}, the test may also take the {@link org.armgals.active.ManualClock}
 * (period {@link #periodMillis()}) that releases its synchronous objects, and a {@link Stepper} of
 * that clock; nothing moves until the test steps it.
 */
@Target({ElementType.TYPE, ElementType.METHOD, ElementType.ANNOTATION_TYPE})
@Retention(RetentionPolicy.RUNTIME)
@Documented
@Inherited
@ExtendWith(ActiveRuntimeExtension.class)
public @interface ActiveTest {

  /** Whether the test gets a manual clock (and a {@link Stepper} of it); default false. */
  boolean manualClock() default false;

  /** The period of the manual clock, in milliseconds of its virtual time; default 10. */
  long periodMillis() default 10;

  /** The number of the runtime's worker threads; default 2. */
  int workers() default 2;

  /**
   * Whether the test fails when one of the runtime's objects failed (an exception while processing
   * an event or a cycle), naming every failure; default true. A test that provokes failures on
   * purpose turns it off and looks at {@link org.armgals.active.RuntimeStats#failures()}.
   */
  boolean failOnObjectFailures() default true;
}
