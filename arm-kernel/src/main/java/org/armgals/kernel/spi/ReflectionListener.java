package org.armgals.kernel.spi;

import org.armgals.kernel.ReflectionEvent;

/**
 * Hears the reflective loop of a kernel ({@link ReflectionEvent}): what a recorder, a live view or
 * a benchmark plugs in with {@link org.armgals.kernel.KernelOptions#withListener}.
 *
 * <p>Threading: called on the thread of the entity or meta the event is about (base-side events on
 * the entity's object, meta-side ones on the meta's object, {@link ReflectionEvent.MetaLost} on the
 * presence thread), so events about one entity from one side come in order, and events of several
 * entities may come concurrently. It must be quick and must not block: it runs inside the loop it
 * tells of. An exception it throws is logged and otherwise ignored.
 */
@FunctionalInterface
public interface ReflectionListener {

  /** A listener that hears nothing: the default. */
  ReflectionListener NONE = event -> {};

  /** One step of the loop. */
  void on(ReflectionEvent event);
}
