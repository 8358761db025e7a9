package org.armgals.kernel;

import org.armgals.representation.State;

/** A base-level entity: an instance of a user kind (or of {@code Entity} itself). */
final class PlainEntity<E extends State> extends EntityImpl<E> {
  PlainEntity(
      KernelImpl kernel, String name, StructuralMetaImpl<E> meta, EntityServant<E> servant) {
    super(kernel, name, meta, servant);
  }
}
