/**
 * The statechart reader and semantics against a public conformance suite: the SCION test
 * framework's charts, the W3C implementation report tests among them ({@code
 * benchmarks/scxml-conformance.sh}).
 */
@NullMarked
package org.armgals.bench.scxml;

import org.jspecify.annotations.NullMarked;
