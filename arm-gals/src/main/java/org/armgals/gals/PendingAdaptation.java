package org.armgals.gals;

/** An adaptation request waiting for its island's adaptation point. */
record PendingAdaptation(EntityImpl<?> entity, String description, Runnable change) {}
