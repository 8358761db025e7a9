/**
 * The pictures a run leaves in its output directory: plots of a trajectory seen from above, of a
 * quantity over time (energy), of adaptations and of the reflective loop on a time line (with
 * XChart), and drawings of a molecule (Java 2D), all as PNG files. Everything here is headless: no
 * display is needed.
 */
@NullMarked
package org.armgals.examples.plot;

import org.jspecify.annotations.NullMarked;
