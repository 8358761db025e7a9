package org.armgals.active.jms;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.Set;
import javax.security.auth.Subject;
import org.apache.activemq.artemis.core.remoting.impl.invm.InVMConnection;
import org.apache.activemq.artemis.core.security.CheckType;
import org.apache.activemq.artemis.core.security.Role;
import org.apache.activemq.artemis.spi.core.protocol.RemotingConnection;
import org.apache.activemq.artemis.spi.core.security.ActiveMQSecurityManager5;
import org.apache.activemq.artemis.spi.core.security.jaas.UserPrincipal;
import org.jspecify.annotations.Nullable;

/**
 * The embedded broker's security: a client of the in-VM acceptor (this JVM's own code) is let in as
 * it is; a client of the network acceptor must give the one login, compared in constant time.
 * Whoever is let in may do everything (the broker serves one application). Thread-safe.
 */
final class BrokerLogin implements ActiveMQSecurityManager5 {
  private final String user;
  private final byte[] password;

  BrokerLogin(String user, String password) {
    this.user = user;
    this.password = password.getBytes(StandardCharsets.UTF_8);
  }

  @Override
  public @Nullable Subject authenticate(
      @Nullable String user,
      @Nullable String password,
      RemotingConnection connection,
      @Nullable String securityDomain) {
    boolean inVm = connection.getTransportConnection() instanceof InVMConnection;
    if (!inVm && !validateUser(user, password)) {
      return null;
    }
    Subject subject = new Subject();
    subject.getPrincipals().add(new UserPrincipal(inVm && user == null ? "in-vm" : this.user));
    return subject;
  }

  @Override
  public boolean authorize(
      @Nullable Subject subject, Set<Role> roles, CheckType checkType, String address) {
    return subject != null;
  }

  @Override
  public boolean validateUser(@Nullable String user, @Nullable String password) {
    return user != null
        && password != null
        && MessageDigest.isEqual(
            this.user.getBytes(StandardCharsets.UTF_8), user.getBytes(StandardCharsets.UTF_8))
        && MessageDigest.isEqual(this.password, password.getBytes(StandardCharsets.UTF_8));
  }

  @Override
  public boolean validateUserAndRole(
      @Nullable String user, @Nullable String password, Set<Role> roles, CheckType checkType) {
    return validateUser(user, password);
  }
}
