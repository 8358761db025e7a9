/**
 * The reified representation of the ARM (paper §3.2, §4.2): the five abstract concepts every
 * representation family implements.
 *
 * <ul>
 *   <li>{@link org.armgals.representation.State}: a possible state of a base-level entity;
 *   <li>{@link org.armgals.representation.StateSpace}: the set of its possible states, which maps
 *       observations to states and makes {@link org.armgals.representation.Activation}s;
 *   <li>{@link org.armgals.representation.Behavior}: a way to go from one state to another (a
 *       method, a transition);
 *   <li>{@link org.armgals.representation.Behaviors}: the set of behaviors an entity can apply (a
 *       method dictionary, the transitions of an automaton);
 *   <li>{@link org.armgals.representation.Activation}: the run-time part, a current state and the
 *       behaviors it is run with.
 * </ul>
 *
 * <p>Three families implement them: procedural ({@code .p}), deterministic finite automata ({@code
 * .dfa}) and statecharts ({@code .sc}). The structural part (space, behaviors) is immutable and
 * shareable between entities; an activation belongs to one entity and is confined to the thread
 * that runs it.
 */
@NullMarked
package org.armgals.representation;

import org.jspecify.annotations.NullMarked;
