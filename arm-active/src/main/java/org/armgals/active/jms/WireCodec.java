package org.armgals.active.jms;

import static java.util.Objects.requireNonNull;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.active.Address;
import org.jspecify.annotations.Nullable;

/**
 * The explicit wire format of events that cross runtimes (docs/architecture.md, runtime semantics
 * 7): no Java serialization. It encodes records and enums of an allow-list, field by field, with
 * values of a closed set of types: null, booleans, numbers, chars, strings, {@link Address}es, byte
 * arrays, lists, string-keyed maps, and further allowed records and enums. A decoder only ever
 * instantiates an allowed type, looked up by its name in the list (never {@code Class.forName}),
 * through its canonical constructor, so the record's own checks run on decoded data too.
 *
 * <p>A body is a version byte, a count, and that many values. Immutable and thread-safe.
 */
final class WireCodec {
  static final byte VERSION = 1;
  static final int MAX_DEPTH = 16;

  private static final byte NULL = 0;
  private static final byte TRUE = 1;
  private static final byte FALSE = 2;
  private static final byte BYTE = 3;
  private static final byte SHORT = 4;
  private static final byte INT = 5;
  private static final byte LONG = 6;
  private static final byte FLOAT = 7;
  private static final byte DOUBLE = 8;
  private static final byte CHAR = 9;
  private static final byte STRING = 10;
  private static final byte ADDRESS = 11;
  private static final byte BYTES = 12;
  private static final byte LIST = 13;
  private static final byte MAP = 14;
  private static final byte RECORD = 15;
  private static final byte ENUM = 16;

  /** How one allowed record is taken apart and put together. */
  private record Shape(
      String name, Class<?> type, Method[] accessors, Type[] types, Constructor<?> constructor) {}

  private final Map<String, Shape> records = new LinkedHashMap<>();
  private final Map<Class<?>, Shape> recordsByClass = new LinkedHashMap<>();
  private final Map<String, Class<?>> enums = new LinkedHashMap<>();
  private final int maxBytes;

  /**
   * @param allowed records and enums that may cross; every record component's type must be one the
   *     codec encodes, and a record or enum it names must be allowed too
   * @param maxBytes the largest body accepted
   * @throws IllegalArgumentException a type that cannot be allowed, naming it and why
   */
  WireCodec(Collection<Class<?>> allowed, int maxBytes) {
    if (maxBytes < 64) {
      throw new IllegalArgumentException("maxBytes must be >= 64, was " + maxBytes);
    }
    this.maxBytes = maxBytes;
    for (Class<?> c : allowed) {
      requireNonNull(c, "allowed type");
      if (c.isEnum()) {
        enums.put(c.getName(), c);
      } else if (c.isRecord()) {
        Shape s = shape(c);
        records.put(s.name(), s);
        recordsByClass.put(c, s);
      } else {
        throw new IllegalArgumentException(
            c.getName() + " cannot be allowed on the wire: expected a record or an enum");
      }
    }
    for (Shape s : records.values()) {
      RecordComponent[] rc = s.type().getRecordComponents();
      for (int i = 0; i < rc.length; i++) {
        checkEncodable(s.type(), rc[i].getName(), rc[i].getGenericType());
      }
    }
  }

  int maxBytes() {
    return maxBytes;
  }

  boolean allows(Class<?> type) {
    return recordsByClass.containsKey(type) || enums.containsKey(type.getName());
  }

  /** The name a type travels under. */
  static String wireName(Class<?> type) {
    return type.getName();
  }

  private static Shape shape(Class<?> c) {
    RecordComponent[] rc = c.getRecordComponents();
    Method[] accessors = new Method[rc.length];
    Type[] types = new Type[rc.length];
    Class<?>[] raw = new Class<?>[rc.length];
    for (int i = 0; i < rc.length; i++) {
      accessors[i] = rc[i].getAccessor();
      types[i] = rc[i].getGenericType();
      raw[i] = rc[i].getType();
    }
    try {
      Constructor<?> ctor = c.getDeclaredConstructor(raw);
      ctor.setAccessible(true);
      for (Method m : accessors) {
        m.setAccessible(true);
      }
      return new Shape(wireName(c), c, accessors, types, ctor);
    } catch (NoSuchMethodException | RuntimeException e) {
      throw new IllegalArgumentException(
          c.getName()
              + " cannot be allowed on the wire: its canonical constructor and accessors must be"
              + " reachable by org.armgals.active (make it public or open its package): "
              + e,
          e);
    }
  }

  private void checkEncodable(Class<?> owner, String component, Type t) {
    if (t instanceof Class<?> c) {
      if (c.isPrimitive()
          || c == Boolean.class
          || c == Byte.class
          || c == Short.class
          || c == Integer.class
          || c == Long.class
          || c == Float.class
          || c == Double.class
          || c == Character.class
          || c == String.class
          || c == Address.class
          || c == byte[].class
          || c == Object.class
          || allows(c)) {
        return;
      }
      if (c.isInterface() && c.isSealed()) {
        for (Class<?> sub : c.getPermittedSubclasses()) {
          checkEncodable(owner, component, sub);
        }
        return;
      }
    } else if (t instanceof ParameterizedType p
        && p.getRawType() instanceof Class<?> raw
        && (raw == List.class || raw == Set.class || raw == Map.class)) {
      Type[] args = p.getActualTypeArguments();
      if (raw == Map.class && args[0] != String.class) {
        throw refuse(owner, component, t, "map keys must be Strings");
      }
      checkEncodable(owner, component, args[args.length - 1]);
      return;
    }
    throw refuse(
        owner,
        component,
        t,
        "expected a primitive, a boxed primitive, String, Address, byte[], Object (any of these),"
            + " List<T>, Set<T>, Map<String, T>, an allowed record or enum, or a sealed interface"
            + " whose permitted types are allowed");
  }

  private static IllegalArgumentException refuse(Class<?> owner, String comp, Type t, String why) {
    return new IllegalArgumentException(
        owner.getName()
            + " cannot be allowed on the wire: component '"
            + comp
            + "' is "
            + t.getTypeName()
            + "; "
            + why);
  }

  // ------------------------------------------------------------------ encoding

  /**
   * One value's bytes, without the body header: {@link #body} joins several.
   *
   * @throws IllegalArgumentException the value holds a type that is not allowed, naming it
   */
  byte[] encodeValue(@Nullable Object value) {
    Out out = new Out();
    write(out, value, 0);
    return out.toByteArray();
  }

  /** A body of the given encoded values. */
  static byte[] body(List<byte[]> values) {
    int size = 5;
    for (byte[] v : values) {
      size += v.length;
    }
    ByteBuffer b = ByteBuffer.allocate(size);
    b.put(VERSION).putInt(values.size());
    for (byte[] v : values) {
      b.put(v);
    }
    return b.array();
  }

  private void write(Out out, @Nullable Object v, int depth) {
    if (depth > MAX_DEPTH) {
      throw new IllegalArgumentException("value nested deeper than " + MAX_DEPTH + " levels");
    }
    switch (v) {
      case null -> out.put(NULL);
      case Boolean b -> out.put(b ? TRUE : FALSE);
      case Byte b -> out.put(BYTE).put(b);
      case Short s -> out.put(SHORT).buffer(2).putShort(s);
      case Integer i -> out.put(INT).buffer(4).putInt(i);
      case Long l -> out.put(LONG).buffer(8).putLong(l);
      case Float f -> out.put(FLOAT).buffer(4).putFloat(f);
      case Double d -> out.put(DOUBLE).buffer(8).putDouble(d);
      case Character c -> out.put(CHAR).buffer(2).putChar(c);
      case String s -> out.put(STRING).string(s);
      case Address a -> {
        out.put(ADDRESS).string(a.runtime());
        out.buffer(8).putLong(a.id());
      }
      case byte[] bytes -> {
        out.put(BYTES).buffer(4).putInt(bytes.length);
        out.bytes(bytes);
      }
      case List<?> list -> {
        out.put(LIST).buffer(4).putInt(list.size());
        for (Object e : list) {
          write(out, e, depth + 1);
        }
      }
      case Set<?> set -> {
        out.put(LIST).buffer(4).putInt(set.size());
        for (Object e : set) {
          write(out, e, depth + 1);
        }
      }
      case Map<?, ?> map -> {
        out.put(MAP).buffer(4).putInt(map.size());
        for (Map.Entry<?, ?> e : map.entrySet()) {
          if (!(e.getKey() instanceof String k)) {
            throw new IllegalArgumentException(
                "map key " + e.getKey() + " is not a String; only String keys cross the wire");
          }
          out.string(k);
          write(out, e.getValue(), depth + 1);
        }
      }
      case Enum<?> e when enums.containsKey(e.getDeclaringClass().getName()) -> {
        out.put(ENUM).string(wireName(e.getDeclaringClass()));
        out.string(e.name());
      }
      case Record r when recordsByClass.containsKey(r.getClass()) -> {
        Shape s = recordsByClass.get(r.getClass());
        out.put(RECORD).string(s.name());
        for (Method m : s.accessors()) {
          try {
            write(out, m.invoke(r), depth + 1);
          } catch (IllegalAccessException | InvocationTargetException e) {
            throw new IllegalArgumentException("cannot read " + m + " of " + r + ": " + e, e);
          }
        }
      }
      default ->
          throw new IllegalArgumentException(
              v.getClass().getName()
                  + " is not allowed on the wire: add it to the transport's allow-list (records"
                  + " and enums only), value "
                  + v);
    }
  }

  // ------------------------------------------------------------------ decoding

  /**
   * The values of a body.
   *
   * @throws WireFormatException anything wrong with it: size, version, truncation, a type that is
   *     not allowed, a value of the wrong type for a component, a record that refuses its values
   */
  List<@Nullable Object> decode(byte[] body) throws WireFormatException {
    if (body.length > maxBytes) {
      throw new WireFormatException(
          "body of " + body.length + " bytes is over the limit of " + maxBytes);
    }
    ByteBuffer in = ByteBuffer.wrap(body);
    try {
      byte version = in.get();
      if (version != VERSION) {
        throw new WireFormatException("unknown wire version " + version + ", expected " + VERSION);
      }
      int n = in.getInt();
      if (n < 1 || n > in.remaining()) {
        throw new WireFormatException(
            "value count " + n + " does not fit a body of " + body.length);
      }
      List<@Nullable Object> out = new ArrayList<>(n);
      for (int i = 0; i < n; i++) {
        out.add(read(in, 0));
      }
      if (in.hasRemaining()) {
        throw new WireFormatException(in.remaining() + " trailing bytes after " + n + " values");
      }
      return out;
    } catch (BufferUnderflowException e) {
      throw new WireFormatException("body truncated (" + body.length + " bytes)", e);
    }
  }

  private @Nullable Object read(ByteBuffer in, int depth) throws WireFormatException {
    if (depth > MAX_DEPTH) {
      throw new WireFormatException("value nested deeper than " + MAX_DEPTH + " levels");
    }
    byte tag = in.get();
    return switch (tag) {
      case NULL -> null;
      case TRUE -> Boolean.TRUE;
      case FALSE -> Boolean.FALSE;
      case BYTE -> in.get();
      case SHORT -> in.getShort();
      case INT -> in.getInt();
      case LONG -> in.getLong();
      case FLOAT -> in.getFloat();
      case DOUBLE -> in.getDouble();
      case CHAR -> in.getChar();
      case STRING -> string(in);
      case ADDRESS -> {
        String runtime = string(in);
        long id = in.getLong();
        try {
          yield new Address(runtime, id);
        } catch (IllegalArgumentException e) {
          throw new WireFormatException("bad address: " + e.getMessage(), e);
        }
      }
      case BYTES -> {
        byte[] b = new byte[length(in, 1)];
        in.get(b);
        yield b;
      }
      case LIST -> {
        int n = length(in, 1);
        List<@Nullable Object> list = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
          list.add(read(in, depth + 1));
        }
        yield Collections.unmodifiableList(list);
      }
      case MAP -> {
        int n = length(in, 2);
        Map<String, @Nullable Object> map = new LinkedHashMap<>();
        for (int i = 0; i < n; i++) {
          String k = string(in);
          map.put(k, read(in, depth + 1));
        }
        yield Collections.unmodifiableMap(map);
      }
      case ENUM -> {
        String name = string(in);
        Class<?> type = enums.get(name);
        if (type == null) {
          throw new WireFormatException("enum type '" + name + "' is not allowed");
        }
        String constant = string(in);
        for (Object c : type.getEnumConstants()) {
          if (((Enum<?>) c).name().equals(constant)) {
            yield c;
          }
        }
        throw new WireFormatException(name + " has no constant '" + constant + "'");
      }
      case RECORD -> readRecord(in, depth);
      default -> throw new WireFormatException("unknown value tag " + tag);
    };
  }

  private Object readRecord(ByteBuffer in, int depth) throws WireFormatException {
    String name = string(in);
    Shape s = records.get(name);
    if (s == null) {
      throw new WireFormatException("type '" + name + "' is not allowed");
    }
    Object[] args = new Object[s.types().length];
    for (int i = 0; i < args.length; i++) {
      Object v = read(in, depth + 1);
      if (v instanceof List<?> list
          && s.types()[i] instanceof ParameterizedType p
          && p.getRawType() == Set.class) {
        v = Collections.unmodifiableSet(new LinkedHashSet<>(list));
      }
      check(s, i, s.types()[i], v);
      args[i] = v;
    }
    try {
      return s.constructor().newInstance(args);
    } catch (InvocationTargetException e) {
      throw new WireFormatException(name + " refused its decoded values: " + e.getCause(), e);
    } catch (ReflectiveOperationException | IllegalArgumentException e) {
      throw new WireFormatException(name + " could not be built from its values: " + e, e);
    }
  }

  /** Whether {@code v} fits the component's declared type, down into lists and maps. */
  private static void check(Shape s, int i, Type t, @Nullable Object v) throws WireFormatException {
    if (t instanceof ParameterizedType p && p.getRawType() instanceof Class<?> raw) {
      if (v == null) {
        return;
      }
      Type[] args = p.getActualTypeArguments();
      Type element = args[args.length - 1];
      if (raw == List.class && v instanceof List<?> list) {
        for (Object e : list) {
          check(s, i, element, e);
        }
        return;
      }
      if (raw == Set.class && v instanceof Set<?> set) {
        for (Object e : set) {
          check(s, i, element, e);
        }
        return;
      }
      if (raw == Map.class && v instanceof Map<?, ?> map) {
        for (Object e : map.values()) {
          check(s, i, element, e);
        }
        return;
      }
    } else if (t instanceof Class<?> c) {
      if (v == null ? !c.isPrimitive() : box(c).isInstance(v)) {
        return;
      }
    }
    throw new WireFormatException(
        s.name()
            + " component "
            + i
            + " is "
            + t.getTypeName()
            + " but the message holds "
            + (v == null ? "null" : v.getClass().getName()));
  }

  private static Class<?> box(Class<?> c) {
    if (!c.isPrimitive()) {
      return c;
    }
    return switch (c.getName()) {
      case "boolean" -> Boolean.class;
      case "byte" -> Byte.class;
      case "short" -> Short.class;
      case "int" -> Integer.class;
      case "long" -> Long.class;
      case "float" -> Float.class;
      case "double" -> Double.class;
      default -> Character.class;
    };
  }

  /** A length that the remaining bytes can hold, at {@code min} bytes per element. */
  private static int length(ByteBuffer in, int min) throws WireFormatException {
    int n = in.getInt();
    if (n < 0 || (long) n * min > in.remaining()) {
      throw new WireFormatException(
          "length " + n + " does not fit the " + in.remaining() + " bytes left");
    }
    return n;
  }

  private static String string(ByteBuffer in) throws WireFormatException {
    int n = length(in, 1);
    ByteBuffer slice = in.slice(in.position(), n);
    in.position(in.position() + n);
    try {
      return StandardCharsets.UTF_8
          .newDecoder()
          .onMalformedInput(CodingErrorAction.REPORT)
          .onUnmappableCharacter(CodingErrorAction.REPORT)
          .decode(slice)
          .toString();
    } catch (CharacterCodingException e) {
      throw new WireFormatException("malformed UTF-8 string of " + n + " bytes", e);
    }
  }

  /** A growable byte buffer. */
  private static final class Out {
    private ByteBuffer b = ByteBuffer.allocate(128);

    ByteBuffer buffer(int room) {
      if (b.remaining() < room) {
        ByteBuffer bigger = ByteBuffer.allocate(Math.max(b.capacity() * 2, b.position() + room));
        b.flip();
        bigger.put(b);
        b = bigger;
      }
      return b;
    }

    Out put(byte v) {
      buffer(1).put(v);
      return this;
    }

    void bytes(byte[] v) {
      buffer(v.length).put(v);
    }

    Out string(String s) {
      byte[] utf8 = s.getBytes(StandardCharsets.UTF_8);
      buffer(4).putInt(utf8.length);
      bytes(utf8);
      return this;
    }

    byte[] toByteArray() {
      byte[] out = new byte[b.position()];
      b.flip();
      b.get(out);
      return out;
    }
  }
}
