package org.armgals.maam.spi;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class LegAnglesTest {

  @Test
  void aPositiveSwingTiltsTowardsTheAzimuth() {
    assertThat(LegAngles.swing(0.3, -Math.PI / 2)).isEqualTo(new LegAngles(0.3, -Math.PI / 2));
    assertThat(LegAngles.swing(0, 1)).isEqualTo(new LegAngles(0, 1));
  }

  @Test
  void aNegativeSwingTiltsTheOppositeWay() {
    assertThat(LegAngles.swing(-0.3, -Math.PI / 2)).isEqualTo(new LegAngles(0.3, Math.PI / 2));
    assertThat(LegAngles.swing(-0.3, 0)).isEqualTo(new LegAngles(0.3, Math.PI));
    assertThat(LegAngles.swing(-0.3, Math.PI)).isEqualTo(new LegAngles(0.3, 0));
  }

  @Test
  void aSwingOutsideTheRangesIsRefused() {
    assertThatThrownBy(() -> LegAngles.swing(0.1, 4))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("azimuth 4.0");
    assertThatThrownBy(() -> LegAngles.swing(Double.NaN, 0))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("elevation NaN");
    assertThatThrownBy(() -> LegAngles.swing(-4, 0))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("elevation 4.0");
  }
}
