package org.armgals.bench.gals;

import org.armgals.maam.Signal;

/** The signal of the MAAM benchmarks. */
record Value(double value) implements Signal {}
