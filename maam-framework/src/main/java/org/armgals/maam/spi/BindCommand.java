package org.armgals.maam.spi;

/** What a leg tip is told to do about binding (an event actuator: each command acts once). */
public enum BindCommand {
  /** Bind to the leg tip it touches, if any. */
  BIND,
  /** Release its binding, if any. */
  UNBIND
}
