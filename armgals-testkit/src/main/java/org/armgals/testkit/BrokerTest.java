package org.armgals.testkit;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Inherited;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * A test of several runtimes on one embedded broker: its methods (and their {@code @BeforeEach} and
 * {@code @AfterEach} methods) may take a {@link TestBroker}, from {@link EmbeddedBrokerExtension}.
 * On a method, the annotation's {@link #failOnObjectFailures()} replaces the class's; {@link
 * #brokerPerTest()} is read from the class only.
 */
@Target({ElementType.TYPE, ElementType.METHOD, ElementType.ANNOTATION_TYPE})
@Retention(RetentionPolicy.RUNTIME)
@Documented
@Inherited
@ExtendWith(EmbeddedBrokerExtension.class)
public @interface BrokerTest {

  /**
   * Whether each test gets a broker of its own, closed after it; default false: the tests of a
   * class share one broker, closed after the last of them, and each test has topics of its own
   * ({@link TestBroker#prefix()}), which isolates them as well at a fraction of the cost.
   */
  boolean brokerPerTest() default false;

  /**
   * Whether the test fails when an object of a runtime made by {@link TestBroker#runtime} failed,
   * naming every failure; default true. A test that provokes failures on purpose turns it off.
   */
  boolean failOnObjectFailures() default true;
}
