package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What a filter means: JMS message-selector semantics over a map of properties
 * (docs/architecture.md, runtime semantics 6).
 */
public class FilterContractTest {

  public static final Map<String, Object> BATTERY =
      Map.of(
          "kind",
          "StateEvent",
          "entityType",
          "Battery",
          "energy",
          18,
          "voltage",
          11.7d,
          "seq",
          42L,
          "charging",
          false);

  public static Stream<Arguments> selectors() {
    return Stream.of(
        Arguments.of("kind = 'StateEvent'", true),
        Arguments.of("kind = 'ActionEvent'", false),
        Arguments.of("kind <> 'ActionEvent'", true),
        Arguments.of("energy < 20", true),
        Arguments.of("energy >= 20", false),
        Arguments.of("voltage BETWEEN 11.5 AND 12.0", true),
        Arguments.of("seq = 42", true),
        Arguments.of("seq > 41 AND energy < 20", true),
        Arguments.of("seq > 42 OR energy < 20", true),
        Arguments.of("NOT (energy < 20)", false),
        Arguments.of("charging", false),
        Arguments.of("charging = FALSE", true),
        Arguments.of("entityType IN ('Battery', 'Motor')", true),
        Arguments.of("entityType NOT IN ('Battery', 'Motor')", false),
        Arguments.of("entityType LIKE 'Bat%'", true),
        Arguments.of("entityType LIKE 'M_tor'", false),
        Arguments.of("energy * 2 + 1 = 37", true),
        Arguments.of("absent IS NULL", true),
        Arguments.of("absent IS NOT NULL", false),
        // unknown in SQL three-valued logic: neither the comparison nor its negation matches
        Arguments.of("absent = 'x'", false),
        Arguments.of("NOT (absent = 'x')", false),
        Arguments.of("absent = 'x' OR energy < 20", true),
        // a string compared with a number is not an error, just no match
        Arguments.of("kind > 3", false),
        Arguments.of("TRUE", true),
        Arguments.of("FALSE", false));
  }

  @ParameterizedTest(name = "{0} -> {1}")
  @MethodSource("selectors")
  void selectorMatchesAsJmsSpecifies(String expression, boolean expected) {
    Filter f = Filter.selector(expression);
    assertThat(f.matches(BATTERY)).isEqualTo(expected);
    assertThat(f.expression()).isEqualTo(expression);
  }

  @Test
  void everyNumberTypeComparesByValue() {
    Filter f = Filter.selector("n = 7");
    for (Object seven : new Object[] {(byte) 7, (short) 7, 7, 7L, 7.0f, 7.0d}) {
      assertThat(f.matches(Map.of("n", seven))).as(seven.getClass().getSimpleName()).isTrue();
    }
  }

  @Test
  void allAcceptsEverythingAndHasNoSelector() {
    assertThat(Filter.ALL.matches(Map.of())).isTrue();
    assertThat(Filter.ALL.matches(BATTERY)).isTrue();
    assertThat(Filter.ALL.expression()).isEmpty();
  }

  @Test
  void blankExpressionIsAll() {
    assertThat(Filter.selector("  ")).isSameAs(Filter.ALL);
  }

  @Test
  void syntaxErrorNamesTheExpression() {
    assertThatThrownBy(() -> Filter.selector("energy <"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'energy <'")
        .hasMessageContaining("selector");
    assertThatThrownBy(() -> Filter.selector("kind = 'unterminated"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'kind = 'unterminated'");
  }

  @Test
  void valueOfAnotherTypeIsRefusedWithItsName() {
    Filter f = Filter.selector("energy < 20");
    assertThatThrownBy(() -> f.matches(Map.of("energy", new java.math.BigDecimal("3"))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'energy'")
        .hasMessageContaining("java.math.BigDecimal");
    assertThatThrownBy(() -> Filter.ALL.matches(Map.of("when", new Object())))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'when'");
  }

  @Test
  void filtersWithTheSameExpressionAreEqual() {
    assertThat(Filter.selector("energy < 20"))
        .isEqualTo(Filter.selector("energy < 20"))
        .hasSameHashCodeAs(Filter.selector("energy < 20"))
        .isNotEqualTo(Filter.selector("energy < 21"));
  }
}
