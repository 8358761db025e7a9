/**
 * The deterministic finite automaton family, ARM[·](DFA) of paper §3.2: a state is a state of the
 * automaton ({@link org.armgals.representation.dfa.DfaState}, with outputs an observer can see),
 * the behaviors are its labelled transitions ({@link
 * org.armgals.representation.dfa.DfaTransition}), and a {@link
 * org.armgals.representation.dfa.DfaSpace} built by its builder refuses a second transition on the
 * same label from a state.
 */
@NullMarked
package org.armgals.representation.dfa;

import org.jspecify.annotations.NullMarked;
