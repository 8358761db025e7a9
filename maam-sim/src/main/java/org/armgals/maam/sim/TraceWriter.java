package org.armgals.maam.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.lang.reflect.RecordComponent;
import java.util.List;
import java.util.Map;
import org.armgals.maam.spi.Leg;

/** Writes the trace: a header line, then one JSON line per control cycle (docs/simulator.md). */
final class TraceWriter {

  static final String FORMAT = "armgals-maam-sim-trace";
  static final int VERSION = 1;

  private final Writer out;
  private final StringBuilder line = new StringBuilder(4096);

  TraceWriter(Writer out) {
    this.out = out;
  }

  void header(
      Scene scene,
      long seed,
      long stepNanos,
      long periodNanos,
      List<Integer> ids,
      Map<String, String> attributes) {
    StringBuilder b = line;
    b.setLength(0);
    b.append("{\"type\":\"header\",\"format\":\"").append(FORMAT).append("\",\"version\":");
    b.append(VERSION).append(",\"scene\":");
    Json.string(b, scene.name());
    b.append(",\"seed\":").append(seed);
    b.append(",\"stepNanos\":").append(stepNanos);
    b.append(",\"periodNanos\":").append(periodNanos);
    b.append(",\"atoms\":").append(ids.toString().replace(" ", ""));
    b.append(",\"attributes\":{");
    boolean first = true;
    for (Map.Entry<String, String> attribute : attributes.entrySet()) {
      if (!first) {
        b.append(',');
      }
      first = false;
      Json.string(b, attribute.getKey());
      b.append(':');
      Json.string(b, attribute.getValue());
    }
    b.append('}');
    b.append(",\"params\":{");
    RecordComponent[] components = AtomParams.class.getRecordComponents();
    for (int i = 0; i < components.length; i++) {
      if (i > 0) {
        b.append(',');
      }
      Json.string(b, components[i].getName());
      b.append(':');
      try {
        b.append(components[i].getAccessor().invoke(scene.params()));
      } catch (ReflectiveOperationException e) {
        throw new IllegalStateException("cannot read AtomParams." + components[i].getName(), e);
      }
    }
    b.append("}}\n");
    write();
  }

  void cycle(long cycle, long timeNanos, List<BodyView> atoms, List<SimEvent> events) {
    StringBuilder b = line;
    b.setLength(0);
    b.append("{\"type\":\"cycle\",\"cycle\":").append(cycle).append(",\"t\":").append(timeNanos);
    b.append(",\"atoms\":[");
    for (int i = 0; i < atoms.size(); i++) {
      if (i > 0) {
        b.append(',');
      }
      BodyView atom = atoms.get(i);
      atom(b, atom.sensors, atom.joints);
    }
    b.append("],\"events\":[");
    for (int i = 0; i < events.size(); i++) {
      if (i > 0) {
        b.append(',');
      }
      event(b, events.get(i));
    }
    b.append("]}\n");
    write();
  }

  /** One atom's readings; {@code joints}: its legs' joint angles, as the physics had them. */
  private static void atom(StringBuilder b, AtomSensors s, double[] joints) {
    b.append("{\"id\":").append(s.id()).append(",\"p\":[");
    Json.number(b, s.position().x());
    b.append(',');
    Json.number(b, s.position().y());
    b.append(',');
    Json.number(b, s.position().z());
    b.append("],\"q\":[");
    Json.number(b, s.orientation().w());
    b.append(',');
    Json.number(b, s.orientation().x());
    b.append(',');
    Json.number(b, s.orientation().y());
    b.append(',');
    Json.number(b, s.orientation().z());
    b.append("],\"tilt\":");
    Json.number(b, s.tilt());
    b.append(",\"energy\":");
    Json.number(b, s.energy());
    b.append(",\"failed\":").append(s.failed()).append(",\"legs\":[");
    for (int i = 0; i < s.legs().size(); i++) {
      LegSensors l = s.legs().get(i);
      b.append(i > 0 ? ",[" : "[");
      Json.number(b, joints[2 * i]);
      b.append(',');
      Json.number(b, joints[2 * i + 1]);
      b.append(',');
      Json.number(b, l.torque1());
      b.append(',');
      Json.number(b, l.torque2());
      b.append(',').append(l.tipContact() ? 1 : 0);
      b.append(',').append(l.locked() ? 1 : 0);
      b.append(',').append(l.neighbour().orElse(-1)).append(',');
      Json.number(b, l.proximity());
      b.append(',').append(l.failed() ? 1 : 0).append(']');
    }
    b.append("]}");
  }

  private static void event(StringBuilder b, SimEvent e) {
    b.append("{\"t\":").append(e.timeNanos()).append(",\"type\":");
    switch (e) {
      case SimEvent.Bound x -> pair(b, "bound", x.atomA(), x.legA(), x.atomB(), x.legB());
      case SimEvent.Unbound x -> pair(b, "unbound", x.atomA(), x.legA(), x.atomB(), x.legB());
      case SimEvent.BindingBroke x -> {
        pair(b, "broke", x.atomA(), x.legA(), x.atomB(), x.legB());
        b.append(",\"force\":");
        Json.number(b, x.force());
      }
      case SimEvent.AtomFailed x -> b.append("\"atomFailed\",\"atom\":").append(x.atom());
      case SimEvent.LegFailed x ->
          b.append("\"legFailed\",\"atom\":")
              .append(x.atom())
              .append(",\"leg\":\"")
              .append(Legs.label(x.leg()))
              .append('"');
      case SimEvent.BatteryEmpty x -> b.append("\"batteryEmpty\",\"atom\":").append(x.atom());
      case SimEvent.MessageLost x ->
          b.append("\"messageLost\",\"atom\":")
              .append(x.from())
              .append(",\"leg\":\"")
              .append(Legs.label(x.fromLeg()))
              .append('"');
      case SimEvent.Note x -> {
        b.append("\"note\",\"atom\":").append(x.atom()).append(",\"text\":");
        Json.string(b, x.text());
      }
    }
    b.append('}');
  }

  private static void pair(StringBuilder b, String type, int a, Leg la, int c, Leg lc) {
    b.append('"').append(type).append("\",\"a\":").append(a).append(",\"legA\":\"");
    b.append(Legs.label(la)).append("\",\"b\":").append(c).append(",\"legB\":\"");
    b.append(Legs.label(lc)).append('"');
  }

  private void write() {
    try {
      out.append(line);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write the simulation trace", e);
    }
  }

  void flush() {
    try {
      out.flush();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot flush the simulation trace", e);
    }
  }
}
