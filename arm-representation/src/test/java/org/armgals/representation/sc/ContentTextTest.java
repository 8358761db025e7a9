package org.armgals.representation.sc;

import static org.assertj.core.api.Assertions.assertThat;

import java.math.BigDecimal;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code <content>} text as ECMAScript's data model reads it (the recommendation's appendix B.2):
 * JSON gives its value, anything else a space-normalized string.
 */
class ContentTextTest {

  // B.2, 578: content that "can be interpeted as JSON" gives "the corresponding ECMAScript
  // structure(s)".
  @Test
  void jsonGivesTheValueItDenotes() {
    assertThat(ContentText.value(" 123 ")).isEqualTo(new BigDecimal("123"));
    assertThat(ContentText.value("-1.5e3")).isEqualTo(new BigDecimal("-1.5e3"));
    assertThat(ContentText.value("\"a \\\"b\\\" \\u00e9\\n\"")).isEqualTo("a \"b\" \u00e9\n");
    assertThat(ContentText.value("true")).isEqualTo(true);
    assertThat(ContentText.value("null")).isNull();
    assertThat(ContentText.value("[]")).isEqualTo(List.of());
    assertThat(ContentText.value("{\"a\": {\"b\": [1, \"x\", null]}, \"c\": false}"))
        .isEqualTo(
            Map.of("a", Map.of("b", Arrays.asList(new BigDecimal("1"), "x", null)), "c", false));
  }

  // B.2, 562: content that is not JSON is "a space-normalized string literal".
  @ParameterizedTest
  @ValueSource(
      strings = {
        "  this is\n\ta  string ",
        "01",
        "1.",
        "{'a': 1}",
        "[1, 2",
        "{\"a\" 1}",
        "\"unterminated",
        "truth",
        "[1] 2"
      })
  void anythingElseIsTheTextSpaceNormalized(String text) {
    assertThat(ContentText.value(text)).isEqualTo(String.join(" ", text.strip().split("\\s+")));
  }

  @Test
  void emptyOrBlankContentIsTheEmptyString() {
    assertThat(ContentText.value("")).isEqualTo("");
    assertThat(ContentText.value(" \n ")).isEqualTo("");
  }
}
