package org.armgals.examples;

import static java.util.Objects.requireNonNull;

import java.io.PrintStream;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Future;

/**
 * Part 1 of the demo: the classic bounded buffer as an active object. {@code put} waits until the
 * buffer is not full and {@code take} until it is not empty; both are guarded requests, so the
 * buffer object itself never blocks: it skips a request whose guard is false and retries it after
 * its state changed.
 */
final class GuardedBufferDemo {
  private GuardedBufferDemo() {}

  /** What part 1 observed. */
  record Result(List<String> taken, int capacity, int mostHeld) {}

  /** The buffer's servant: plain sequential code, run by its active object. */
  static final class Buffer {
    private final ArrayDeque<String> items = new ArrayDeque<>();
    private final int capacity;
    private int mostHeld;

    Buffer(int capacity) {
      this.capacity = capacity;
    }

    boolean notFull() {
      return items.size() < capacity;
    }

    boolean notEmpty() {
      return !items.isEmpty();
    }

    void put(String item) {
      items.addLast(item);
      mostHeld = Math.max(mostHeld, items.size());
    }

    String take() {
      return items.removeFirst();
    }

    int mostHeld() {
      return mostHeld;
    }
  }

  /** Puts its items one after the other, each once the buffer has room. */
  static final class Producer {
    private final String name;
    private final ActiveRef<Buffer> buffer;

    Producer(String name, ActiveRef<Buffer> buffer) {
      this.name = requireNonNull(name, "name");
      this.buffer = requireNonNull(buffer, "buffer");
    }

    void produce(int count) {
      for (int i = 1; i <= count; i++) {
        String item = name + i;
        // touch() waits by necessity: this producer (only) waits while the buffer is full.
        buffer.callWhen(Buffer::notFull, b -> put(b, item)).touch();
      }
    }

    private static String put(Buffer b, String item) {
      b.put(item);
      return item;
    }
  }

  /** Takes items, each once the buffer has one. */
  static final class Consumer {
    private final ActiveRef<Buffer> buffer;

    Consumer(ActiveRef<Buffer> buffer) {
      this.buffer = requireNonNull(buffer, "buffer");
    }

    List<String> consume(int count) {
      List<String> got = new ArrayList<>();
      for (int i = 0; i < count; i++) {
        got.add(buffer.callWhen(Buffer::notEmpty, Buffer::take).getValue());
      }
      return got;
    }
  }

  static Result run(ActiveRuntime runtime, PrintStream out, Duration timeout) {
    int capacity = 2;
    int each = 5;
    ActiveObject<Buffer> buffer = runtime.spawn(new Buffer(capacity));
    ActiveObject<Consumer> consumer = runtime.spawn(new Consumer(buffer));
    Future a = runtime.spawn(new Producer("a", buffer)).signal(p -> p.produce(each));
    Future b = runtime.spawn(new Producer("b", buffer)).signal(p -> p.produce(each));
    List<String> taken = consumer.call(c -> c.consume(2 * each)).getValue(timeout);
    a.touch(timeout);
    b.touch(timeout);
    int mostHeld = buffer.call(Buffer::mostHeld).getValue(timeout);

    out.println("1. A bounded buffer of " + capacity + ": put waits while it is full, take while");
    out.println("   it is empty (guarded requests; producers a and b put " + each + " items each)");
    out.println("   consumer took: " + String.join(" ", taken));
    out.println("   each producer's items came out in the order it put them: " + inOrder(taken));
    out.println("   most items the buffer ever held: " + mostHeld);
    return new Result(taken, capacity, mostHeld);
  }

  /** Whether the items of each producer appear in increasing order. */
  static boolean inOrder(List<String> taken) {
    for (String producer : List.of("a", "b")) {
      List<Integer> numbers =
          taken.stream()
              .filter(s -> s.startsWith(producer))
              .map(s -> Integer.parseInt(s.substring(producer.length())))
              .toList();
      if (!numbers.equals(numbers.stream().sorted().toList())) {
        return false;
      }
    }
    return true;
  }
}
