package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.io.Reader;
import java.io.StringReader;

/**
 * Reads and writes statechart definitions in a subset of W3C SCXML 1.0 (docs/representations.md
 * lists it): {@code scxml}, {@code state}, {@code parallel}, {@code final}, {@code initial}, {@code
 * history}, {@code transition} (event, cond as a guard's name or in the condition language, target,
 * type), executable content ({@code raise}, {@code log}, and {@code arm:action} of the namespace
 * {@value #ARM_NAMESPACE}) in {@code onentry}, {@code onexit}, transitions and default transitions.
 * Anything else is refused with an {@link ScxmlException} naming the element and its line.
 *
 * <p>Transitions get their id from an {@code arm:id} attribute, or else {@code source#n}, the n-th
 * transition of its source (from 1). {@link #write} writes {@code arm:id} only where the id is not
 * that default, and puts each state's transitions among its children where the definition's order
 * of transitions (document order, for a definition read) places them, so that {@code
 * read(write(d))} equals {@code d} for every {@code d} read. A definition built in Java whose
 * transitions are in another order comes back with them in document order.
 */
public final class Scxml {
  /** The SCXML namespace. */
  public static final String NAMESPACE = "http://www.w3.org/2005/07/scxml";

  /** The namespace of armgals' additions: {@code action} elements and {@code id} attributes. */
  public static final String ARM_NAMESPACE = "http://armgals.org/scxml";

  /** The {@code target} of a {@code <send>} to the chart's own internal queue. */
  static final String INTERNAL_TARGET = "#_internal";

  /** The {@code type} of a {@code <send>} by the SCXML event I/O processor, the default. */
  static final String SCXML_PROCESSOR = "http://www.w3.org/TR/scxml/#SCXMLEventProcessor";

  private Scxml() {}

  /**
   * The definition an SCXML document holds.
   *
   * @throws ScxmlException if the document is malformed or uses what is not supported
   */
  public static ScDefinition read(String document) {
    return read(new StringReader(requireNonNull(document, "document")));
  }

  /**
   * The definition an SCXML document holds; {@code reader} is read to the end, not closed.
   *
   * @throws ScxmlException if the document is malformed or uses what is not supported
   */
  public static ScDefinition read(Reader reader) {
    return ScxmlReader.read(requireNonNull(reader, "reader"));
  }

  /**
   * {@code definition} as an SCXML document.
   *
   * @throws IllegalArgumentException if a transition's source is not a state of the definition
   */
  public static String write(ScDefinition definition) {
    return ScxmlWriter.write(requireNonNull(definition, "definition"));
  }

  /** The id {@link #read} gives the {@code n}-th transition (from 1) of {@code source}. */
  public static String defaultTransitionId(String source, int n) {
    return source + "#" + n;
  }
}
