/**
 * The simulator's real-time factor: how many seconds of virtual time maam-sim runs per second of
 * real time for grids of atoms with simple controllers ({@code benchmarks/sim.sh}).
 */
@NullMarked
package org.armgals.bench.sim;

import org.jspecify.annotations.NullMarked;
