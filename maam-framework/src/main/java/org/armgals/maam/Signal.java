package org.armgals.maam;

/**
 * A value that flows between behavior modules on their {@link Port}s during one cycle: a stimulus
 * from a perceptor, reaction parameters from a reactor (paper §5.4, step 3: the programmer's signal
 * classes implement this). Signals must be immutable, so a record is the natural implementation: a
 * signal emitted once may be read by several modules and kept by a suppressor.
 */
public interface Signal {}
