/**
 * Speed and memory figures of armgals: JMH micro-benchmarks in {@code org.armgals.bench.jmh} and a
 * Savina-style suite with an Apache Pekko baseline in {@code org.armgals.bench.savina}. See {@code
 * docs/benchmarks.md}.
 */
@NullMarked
package org.armgals.bench;

import org.jspecify.annotations.NullMarked;
