package org.armgals.active;

import java.util.ArrayList;
import java.util.List;

/**
 * A servant that writes down, in processing order, every {@link Tagged} event it processes. Only
 * its object touches it; read it through a request, or after the object's last activation.
 */
final class Journal implements EventProcessor {
  private final List<Tagged> processed = new ArrayList<>();

  @Override
  public void process(Event event) {
    processed.add((Tagged) event);
  }

  int size() {
    return processed.size();
  }

  List<Tagged> processed() {
    return processed;
  }
}
