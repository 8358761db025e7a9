package org.armgals.maam;

/** The signal of the tests: a number. */
record Num(int value) implements Signal {}
