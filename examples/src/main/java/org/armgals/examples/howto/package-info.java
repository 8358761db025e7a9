/**
 * The code quoted in {@code README.md} and {@code docs/}: every region between {@code //
 * tag::name[]} and {@code // end::name[]} appears, unchanged, in a Markdown block marked {@code
 * <!-- snippet: path#name -->}, and {@code DocSnippetsTest} fails when the two differ. Each class
 * has a method that runs its snippets, so that {@code HowtoTest} can check they do what the docs
 * say.
 */
@NullMarked
package org.armgals.examples.howto;

import org.jspecify.annotations.NullMarked;
