package org.armgals.maam;

import java.util.ArrayList;
import java.util.List;

/**
 * A reactor for the tests: emits on {@link #OUT} the sum of its inputs plus its bias, or nothing
 * when its bias is 0, it has inputs and none has a signal; logs its runs into a shared trace.
 */
final class Node implements Reactor {

  static final Port<Num> OUT = Port.of("out", Num.class);

  private final String name;
  private final List<Port<?>> inputs;
  private final int bias;
  private final List<String> trace;

  Node(String name, int inputCount, int bias, List<String> trace) {
    this.name = name;
    List<Port<?>> ports = new ArrayList<>();
    for (int i = 0; i < inputCount; i++) {
      ports.add(in(i));
    }
    this.inputs = List.copyOf(ports);
    this.bias = bias;
    this.trace = trace;
  }

  static Port<Num> in(int i) {
    return Port.of("in" + i, Num.class);
  }

  @Override
  public String name() {
    return name;
  }

  @Override
  public List<Port<?>> inputs() {
    return inputs;
  }

  @Override
  public List<Port<?>> outputs() {
    return List.of(OUT);
  }

  @Override
  @SuppressWarnings("unchecked")
  public void react(Inputs in, Outputs out) {
    trace.add(name);
    int sum = bias;
    boolean any = inputs.isEmpty() || bias != 0;
    for (Port<?> port : inputs) {
      Num value = in.get((Port<Num>) port);
      if (value != null) {
        sum += value.value();
        any = true;
      }
    }
    if (any) {
      out.emit(OUT, new Num(sum));
    }
  }
}
