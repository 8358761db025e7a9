package org.armgals.gals;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;

/**
 * An island's per-cycle trace and its running SHA-256. Lines are added by the thread that runs the
 * cycles, after every entity has finished, in spawn order: their order depends on nothing but the
 * inputs.
 */
final class Trace {
  private final boolean on;
  private final List<String> lines = new ArrayList<>();
  private final MessageDigest digest;

  Trace(boolean on) {
    this.on = on;
    try {
      this.digest = MessageDigest.getInstance("SHA-256");
    } catch (NoSuchAlgorithmException e) {
      throw new IllegalStateException("every JDK has SHA-256", e);
    }
  }

  boolean on() {
    return on;
  }

  synchronized void add(String line) {
    if (!on) {
      return;
    }
    lines.add(line);
    digest.update(line.getBytes(StandardCharsets.UTF_8));
    digest.update((byte) '\n');
  }

  synchronized List<String> lines() {
    return List.copyOf(lines);
  }

  synchronized String hash() {
    try {
      return HexFormat.of().formatHex(((MessageDigest) digest.clone()).digest());
    } catch (CloneNotSupportedException e) {
      throw new IllegalStateException("the JDK's SHA-256 can be cloned", e);
    }
  }
}
