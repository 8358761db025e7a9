/**
 * The JMS transport: runtimes of any JVMs linked through an Apache ActiveMQ Artemis broker
 * (docs/architecture.md, runtime semantics 5; docs/decisions/0058). {@link
 * org.armgals.active.jms.JmsTransport} carries events, requests and answers on the paper's topics
 * and keeps a name service; {@link org.armgals.active.jms.EmbeddedBroker} starts a broker in this
 * JVM; {@link org.armgals.active.jms.Presence} beats on a topic and tells its {@link
 * org.armgals.active.spi.PresenceListener}s when another runtime joins, leaves or falls silent.
 *
 * <p>The package plugs into the core through its SPI ({@link org.armgals.active.spi.Transport},
 * {@link org.armgals.active.spi.RemoteAnswer}); the core names nothing of it. Its dependencies, the
 * Artemis client and server and the Jakarta Messaging API, are optional dependencies of arm-active:
 * a user who distributes adds them (docs/user-guide.md).
 */
@NullMarked
package org.armgals.active.jms;

import org.jspecify.annotations.NullMarked;
