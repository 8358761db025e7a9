/**
 * The broker benchmark ({@code benchmarks/broker.sh}): one-way events and request/reply round trips
 * over one embedded Apache Artemis broker, in-VM and over netty on 127.0.0.1, measured with a plain
 * Jakarta JMS producer and consumer (the {@code raw} baseline) and with two armgals runtimes over
 * the JMS transport, run by {@link org.armgals.bench.broker.BrokerBench}.
 */
@NullMarked
package org.armgals.bench.broker;

import org.jspecify.annotations.NullMarked;
