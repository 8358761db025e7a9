package org.armgals.examples.robots;

/**
 * Touches what an atom's JVM touches that JDK 24 and later warn about: netty's {@code
 * sun.misc.Unsafe} allocation and Artemis' native libaio.
 */
final class QuietJvmMain {
  private QuietJvmMain() {}

  public static void main(String[] args) {
    System.out.println("netty unsafe " + io.netty.util.internal.PlatformDependent.hasUnsafe());
    System.out.println(
        "libaio " + org.apache.activemq.artemis.nativo.jlibaio.LibaioContext.isLoaded());
  }
}
