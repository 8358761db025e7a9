package org.armgals.active.jms;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicInteger;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.jms.JmsFixture.Level;
import org.armgals.active.jms.JmsFixture.Measure;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Reading;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.Test;

/** The wire codec: what it encodes, and that hostile bytes never get further than a rejection. */
class WireCodecTest {
  static final AtomicInteger TRAPS_MADE = new AtomicInteger();

  /** Never allowed: if the codec ever built one, or even initialized the class, the count shows. */
  record Trap(@Nullable Address sender, Address destination, String text) implements Event {
    static {
      TRAPS_MADE.incrementAndGet();
    }

    Trap {
      TRAPS_MADE.incrementAndGet();
    }
  }

  record Positive(int n) {
    Positive {
      if (n <= 0) {
        throw new IllegalArgumentException("n must be > 0, was " + n);
      }
    }
  }

  record HoldsObject(Object anything) {}

  record HoldsNested(Reading reading) {}

  record HoldsSet(java.util.Set<String> names) {}

  record HoldsRunnable(Runnable task) {}

  record HoldsThreads(java.util.Set<Thread> threads) {}

  sealed interface Shape permits Square, Circle {}

  record Square(double side) implements Shape {}

  record Circle(double radius) implements Shape {}

  record HoldsShape(Shape shape) {}

  static final WireCodec CODEC = new WireCodec(List.of(JmsFixture.ALLOWED), 4096);

  static final Address TO = new Address("b", 1);

  static byte[] body(Object... values) {
    return WireCodec.body(Arrays.stream(values).map(CODEC::encodeValue).toList());
  }

  @Test
  void allowedValuesRoundTrip() throws Exception {
    Measure m =
        new Measure(
            new Address("a", 7),
            TO,
            new Reading("x", -1.5, Level.LOW, List.of(4, 5)),
            Map.of("k", 9L),
            new byte[] {9, 8});
    List<@Nullable Object> out = CODEC.decode(body(m, new Ping(null, TO, 3)));
    Measure back = (Measure) out.get(0);
    assertThat(back.sender()).isEqualTo(m.sender());
    assertThat(back.reading()).isEqualTo(m.reading());
    assertThat(back.counts()).isEqualTo(m.counts());
    assertThat(back.raw()).containsExactly(9, 8);
    assertThat(out.get(1)).isEqualTo(new Ping(null, TO, 3));
  }

  @Test
  void onlyRecordsAndEnumsWithEncodableComponentsCanBeAllowed() {
    assertThatThrownBy(() -> new WireCodec(List.of(String.class), 4096))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("java.lang.String")
        .hasMessageContaining("record or an enum");
    assertThatThrownBy(() -> new WireCodec(List.of(HoldsRunnable.class), 4096))
        .as("an interface that is not sealed")
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'task'")
        .hasMessageContaining("java.lang.Runnable");
    assertThatThrownBy(() -> new WireCodec(List.of(HoldsShape.class, Square.class), 4096))
        .as("a sealed interface whose permitted types are not all allowed")
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("Circle");
    assertThatThrownBy(() -> new WireCodec(List.of(HoldsNested.class), 4096))
        .as("a nested record must be allowed too")
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("Reading");
    assertThatThrownBy(() -> new WireCodec(List.of(HoldsThreads.class), 4096))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("java.lang.Thread");
  }

  @Test
  void objectSetAndSealedInterfaceComponentsCarryOnlyWhatTheCodecEncodes() throws Exception {
    WireCodec codec =
        new WireCodec(
            List.of(
                HoldsObject.class,
                HoldsSet.class,
                HoldsShape.class,
                Square.class,
                Circle.class,
                Reading.class,
                Level.class),
            4096);
    Reading reading = new Reading("x", 1.5, Level.LOW, List.of(1));
    for (Object v : List.of("s", 2.5, List.of(1L, "two"), Map.of("k", true), reading)) {
      byte[] b = WireCodec.body(List.of(codec.encodeValue(new HoldsObject(v))));
      assertThat(codec.decode(b)).containsExactly(new HoldsObject(v));
    }
    HoldsSet set = new HoldsSet(java.util.Set.of("a", "b"));
    assertThat(codec.decode(WireCodec.body(List.of(codec.encodeValue(set))))).containsExactly(set);
    HoldsShape shape = new HoldsShape(new Circle(2));
    assertThat(codec.decode(WireCodec.body(List.of(codec.encodeValue(shape)))))
        .containsExactly(shape);
    assertThatThrownBy(() -> codec.encodeValue(new HoldsObject(new Positive(1))))
        .as("an Object component holding a type not allowed")
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining(Positive.class.getName());
  }

  @Test
  void aValueOfATypeNotAllowedIsRefusedWhenEncoded() {
    assertThatThrownBy(() -> CODEC.encodeValue(new Trap(null, TO, "x")))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining(Trap.class.getName());
  }

  /** A body naming a record type by hand, with the given encoded components. */
  static byte[] recordBody(String typeName, byte[]... components) {
    ByteBuffer b = ByteBuffer.allocate(4096);
    byte[] name = typeName.getBytes(StandardCharsets.UTF_8);
    b.put(WireCodec.VERSION).putInt(1).put((byte) 15).putInt(name.length).put(name);
    for (byte[] c : components) {
      b.put(c);
    }
    return Arrays.copyOf(b.array(), b.position());
  }

  @Test
  void hostileBodiesAreRejectedWithAReason() {
    byte[] nul = CODEC.encodeValue(null);
    byte[] to = CODEC.encodeValue(TO);
    byte[] text = CODEC.encodeValue("x");
    List<byte[]> hostile =
        List.of(
            new byte[0],
            new byte[] {42},
            new byte[] {WireCodec.VERSION, 0, 0, 0, 1},
            new byte[] {WireCodec.VERSION, 0x7f, -1, -1, -1, 0},
            recordBody(Trap.class.getName(), nul, to, text),
            recordBody("java.lang.Runtime"),
            recordBody(Ping.class.getName(), nul, to, text), // a String where a long goes
            recordBody(Ping.class.getName(), nul, to), // a component missing
            new byte[] {
              WireCodec.VERSION, 0, 0, 0, 1, 10, 0x7f, -1, -1, -1
            }, // string longer than all
            new byte[] {WireCodec.VERSION, 0, 0, 0, 1, 10, 0, 0, 0, 2, (byte) 0xc3, (byte) 0x28},
            new byte[] {WireCodec.VERSION, 0, 0, 0, 1, 99},
            new byte[4097]);
    for (byte[] h : hostile) {
      assertThatThrownBy(() -> CODEC.decode(h))
          .as(Arrays.toString(Arrays.copyOf(h, Math.min(h.length, 16))))
          .isInstanceOf(WireFormatException.class);
    }
    assertThat(TRAPS_MADE).hasValue(0);
  }

  @Test
  void aDeeplyNestedListIsRefusedNotOverflowed() {
    ByteBuffer b = ByteBuffer.allocate(4000);
    b.put(WireCodec.VERSION).putInt(1);
    while (b.remaining() > 10) {
      b.put((byte) 13).putInt(1);
    }
    byte[] bomb = Arrays.copyOf(b.array(), b.position());
    assertThatThrownBy(() -> CODEC.decode(bomb))
        .isInstanceOf(WireFormatException.class)
        .hasMessageContaining("nested deeper");
  }

  @Test
  void aRecordThatRefusesItsDecodedValuesIsRejected() throws Exception {
    WireCodec c = new WireCodec(List.of(Positive.class), 4096);
    assertThat(c.decode(WireCodec.body(List.of(c.encodeValue(new Positive(3))))))
        .containsExactly(new Positive(3));
    byte[] zero = recordBody(Positive.class.getName(), c.encodeValue(0));
    assertThatThrownBy(() -> c.decode(zero))
        .isInstanceOf(WireFormatException.class)
        .hasMessageContaining("n must be > 0, was 0");
  }

  @Test
  void generatedBodiesNeverCrashAndNeverBuildAnUnlistedType() {
    SplittableRandom random = new SplittableRandom(20261122);
    byte[] valid =
        body(
            new Measure(
                null,
                TO,
                new Reading("r", 1, Level.HIGH, List.of(1)),
                Map.of("a", 1L),
                new byte[] {1}));
    byte[] trap =
        recordBody(
            Trap.class.getName(),
            CODEC.encodeValue(null),
            CODEC.encodeValue(TO),
            CODEC.encodeValue("t"));
    int decoded = 0;
    int rejected = 0;
    for (int i = 0; i < 30_000; i++) {
      byte[] b = generated(random, i % 3 == 0 ? valid : trap);
      try {
        for (Object v : CODEC.decode(b)) {
          assertThat(v == null || CODEC.allows(v.getClass()) || isSimple(v)).as("%s", v).isTrue();
        }
        decoded++;
      } catch (WireFormatException e) {
        rejected++;
      }
    }
    assertThat(decoded + rejected).isEqualTo(30_000);
    assertThat(rejected).isGreaterThan(15_000);
    assertThat(TRAPS_MADE).hasValue(0);
  }

  private static boolean isSimple(Object v) {
    return v instanceof String
        || v instanceof Number
        || v instanceof Boolean
        || v instanceof Character
        || v instanceof Address
        || v instanceof byte[]
        || v instanceof List<?>
        || v instanceof Map<?, ?>;
  }

  /** Random bytes, or a seed with a few bytes flipped, truncated or extended. */
  static byte[] generated(SplittableRandom random, byte[] seed) {
    switch (random.nextInt(4)) {
      case 0 -> {
        byte[] b = new byte[random.nextInt(64)];
        random.nextBytes(b);
        if (b.length > 0 && random.nextBoolean()) {
          b[0] = WireCodec.VERSION;
        }
        return b;
      }
      case 1 -> {
        return Arrays.copyOf(seed, random.nextInt(seed.length + 1));
      }
      case 2 -> {
        byte[] b = Arrays.copyOf(seed, seed.length + 1 + random.nextInt(16));
        return b;
      }
      default -> {
        byte[] b = seed.clone();
        for (int k = 1 + random.nextInt(4); k > 0; k--) {
          b[random.nextInt(b.length)] = (byte) random.nextInt(256);
        }
        return b;
      }
    }
  }
}
