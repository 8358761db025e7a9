/**
 * The statechart family, ARM[·](SC) of paper §3.2: a {@link
 * org.armgals.representation.sc.Statechart} is built from an {@link
 * org.armgals.representation.sc.ScDefinition} (states with hierarchy, orthogonal regions, shallow
 * and deep history, final states, entry and exit actions) and named {@link
 * org.armgals.representation.sc.Guard}s; its states are {@link
 * org.armgals.representation.sc.Configuration}s, its behaviors are its transitions, and a dispatch
 * is one run-to-completion step of the W3C SCXML algorithm. {@link
 * org.armgals.representation.sc.Scxml} reads and writes a documented subset of W3C SCXML.
 *
 * <p>Actions are not run by the chart: they are named, and each step lists the actions of its
 * transition (exits, transition content, entries) for the entity to run, so that a model can replay
 * transitions without doing anything (docs/decisions/0012).
 */
@NullMarked
package org.armgals.representation.sc;

import org.jspecify.annotations.NullMarked;
