package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** A loop's record read back from its file (a meta level's JVM writes one) is the one written. */
class LoopRecorderTest {

  @Test
  void aRecordReadBackIsWrittenAgainAsItWasWholeDoublesIncluded() {
    Map<String, Object> input = new LinkedHashMap<>();
    input.put("phase", 0.0);
    input.put("stride", 0.30000000000000004);
    input.put("steps", 3L);
    input.put("large", 1.0E10);
    Map<String, Object> record = new LinkedHashMap<>();
    record.put("cycle", 7L);
    record.put("event", "requested");
    record.put("input", input);
    String line = LoopJson.write(record);

    Map<?, ?> parsed = (Map<?, ?>) TraceJson.parse(line);
    List<Map<String, Object>> back = LoopRecorder.merge(List.of(LoopRecorder.read(parsed, 0)));

    assertThat(LoopJson.write(back.get(0))).isEqualTo(line).contains("\"phase\":0.0");
  }
}
