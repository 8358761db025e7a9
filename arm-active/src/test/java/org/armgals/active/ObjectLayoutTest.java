package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.openjdk.jol.info.ClassLayout;
import org.openjdk.jol.info.FieldLayout;

/**
 * How the JVM lays out an active object (decision 0078). Senders read and write {@link
 * SenderSide}'s fields on every send; the object's activation reads {@link ReceiverSide}'s on every
 * event. A cache line holding one of each moves between the two cores on every event.
 */
class ObjectLayoutTest {
  private static final int LINE = 64;

  /** Objects start at multiples of 8 bytes, so an object sits at one of 8 places in a line. */
  private static final int ALIGNMENT = 8;

  private final ClassLayout layout = ClassLayout.parseClass(Core.class);

  @Test
  void theSendersFieldsShareNoLineWithWhatLiesBeforeTheObject() {
    // Usually its servant, made just before it and written by its activation on every event.
    assertThat(fieldsOf(SenderSide.class))
        .extracting(FieldLayout::name)
        .containsExactlyInAnyOrder("config", "state", "tail", "size");
    assertThat(fieldsOf(SenderSide.class))
        .allSatisfy(f -> assertThat(f.offset()).as(f.name()).isGreaterThanOrEqualTo(LINE));
  }

  @Test
  void whatEverySendWritesSharesALineWithTheReceivingSideAtTwoPlacesInEightAtMost() {
    List<FieldLayout> written =
        fieldsOf(SenderSide.class).stream()
            .filter(f -> f.name().equals("tail") || f.name().equals("size"))
            .toList();
    List<FieldLayout> receiver = fieldsOf(ReceiverSide.class);
    assertThat(receiver).extracting(FieldLayout::name).contains("servant", "rare", "stopped");
    List<Integer> sharing = new ArrayList<>();
    for (int place = 0; place < LINE; place += ALIGNMENT) {
      for (FieldLayout s : written) {
        for (FieldLayout r : receiver) {
          if (!Collections.disjoint(lines(place, r), lines(place, s)) && !sharing.contains(place)) {
            sharing.add(place);
          }
        }
      }
    }
    // Two is the least these fields allow in 88 bytes, and an idle object may take 100 in all.
    assertThat(sharing).as("places in a line where they share one").hasSizeLessThanOrEqualTo(2);
  }

  @Test
  void anActiveObjectFitsAnIdleObjectsBudget() {
    // 100 bytes for an idle object in all (decision 0045), its entry in the object table included.
    assertThat(layout.instanceSize()).isLessThanOrEqualTo(88);
  }

  @Test
  void coreItselfDeclaresNoField() {
    // Its fields would be laid out after the senders' and share their line.
    assertThat(fieldsOf(Core.class)).isEmpty();
  }

  private List<FieldLayout> fieldsOf(Class<?> declaring) {
    return layout.fields().stream().filter(f -> f.hostClass().equals(declaring.getName())).toList();
  }

  /** The lines, numbered from the line the object starts in, that a field's bytes fall in. */
  private static List<Long> lines(int place, FieldLayout f) {
    long first = (place + f.offset()) / LINE;
    long last = (place + f.offset() + f.size() - 1) / LINE;
    return first == last ? List.of(first) : List.of(first, last);
  }
}
