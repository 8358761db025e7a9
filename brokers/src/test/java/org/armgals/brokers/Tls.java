package org.armgals.brokers;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.TimeSource;

/**
 * A broker's TLS material made for one test class with the JDK's {@code keytool}: a key store
 * holding a fresh self-signed key pair for {@code 127.0.0.1} and {@code localhost}, and a trust
 * store holding only its certificate, both PKCS#12 under one random password.
 */
record Tls(Path keyStore, Path trustStore, String password) {
  private static final Duration KEYTOOL_TIMEOUT = Duration.ofSeconds(60);

  Tls {
    requireNonNull(keyStore, "keyStore");
    requireNonNull(trustStore, "trustStore");
    requireNonNull(password, "password");
  }

  /** Makes the stores in {@code dir} with the keytool of {@code javaHome}. */
  static Tls generate(Path dir, Path javaHome, TimeSource time) throws InterruptedException {
    String password = BrokerSpec.Credentials.random("tls").password();
    Tls tls = new Tls(dir.resolve("broker-keys.p12"), dir.resolve("client-trust.p12"), password);
    Path certificate = dir.resolve("broker.pem");
    Path keytool = javaHome.resolve("bin/keytool");
    tls.run(
        "keytool -genkeypair",
        time,
        dir,
        List.of(
            keytool.toString(),
            "-genkeypair",
            "-alias",
            "broker",
            "-keyalg",
            "EC",
            "-groupname",
            "secp256r1",
            "-dname",
            "CN=localhost",
            "-ext",
            "SAN=ip:127.0.0.1,dns:localhost",
            "-validity",
            "2",
            "-storetype",
            "PKCS12",
            "-keystore",
            tls.keyStore.toString(),
            "-storepass",
            password));
    tls.run(
        "keytool -exportcert",
        time,
        dir,
        List.of(
            keytool.toString(),
            "-exportcert",
            "-rfc",
            "-alias",
            "broker",
            "-keystore",
            tls.keyStore.toString(),
            "-storepass",
            password,
            "-file",
            certificate.toString()));
    tls.run(
        "keytool -importcert",
        time,
        dir,
        List.of(
            keytool.toString(),
            "-importcert",
            "-noprompt",
            "-alias",
            "broker",
            "-file",
            certificate.toString(),
            "-storetype",
            "PKCS12",
            "-keystore",
            tls.trustStore.toString(),
            "-storepass",
            password));
    return tls;
  }

  private void run(String what, TimeSource time, Path dir, List<String> command)
      throws InterruptedException {
    try (ChildProcess keytool =
        ChildProcess.start(
            what,
            new ProcessBuilder(new ArrayList<>(command)),
            dir.resolve(what.replace(' ', '-') + ".log"),
            time)) {
      int code = keytool.awaitExit(KEYTOOL_TIMEOUT);
      if (code != 0) {
        throw new IllegalStateException(what + " exited with " + code + ":\n" + keytool.tail());
      }
    }
  }

  /** The acceptor's URL parameters, in broker.xml's {@code ;}-separated form. */
  String acceptorParameters() {
    return "sslEnabled=true;keyStorePath="
        + keyStore
        + ";keyStorePassword="
        + password
        + ";keyStoreType=PKCS12;";
  }

  /** A client's URL query, trusting the broker's certificate only. */
  String clientQuery() {
    return "sslEnabled=true&trustStorePath="
        + trustStore
        + "&trustStorePassword="
        + password
        + "&trustStoreType=PKCS12";
  }
}
