/**
 * The live view: {@code armgals run <robot> --live} and {@code armgals view <trace>} serve a page
 * on 127.0.0.1 ({@link org.armgals.examples.live.LiveServer}) that shows the molecule from above
 * and from the side in its scene, the robots' schemas and schedules, the energy, and the reflective
 * loop as it goes; a trace is played back by a {@link org.armgals.examples.live.Player}.
 */
@NullMarked
package org.armgals.examples.live;

import org.jspecify.annotations.NullMarked;
