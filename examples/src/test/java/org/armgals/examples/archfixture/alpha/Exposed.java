package org.armgals.examples.archfixture.alpha;

/** Fixture: a public class that is not in alpha's API list. */
public final class Exposed {}
