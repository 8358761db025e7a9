/**
 * The robot of {@code docs/maam-guide.md}, written in the paper's four steps against the public API
 * only, and run on a manual clock with the test-double body.
 */
@NullMarked
package org.armgals.maam.guide;

import org.jspecify.annotations.NullMarked;
