package org.armgals.maam.sim;

/**
 * A fixed obstacle of a scene. Steps and walls are boxes; a pipe is a hollow tube the atoms can
 * move in.
 */
public sealed interface Obstacle {

  /**
   * A box, axis-aligned.
   *
   * @param center centre (m)
   * @param size full lengths along x, y and z (m), each positive
   */
  record Box(Vec3 center, Vec3 size) implements Obstacle {
    /** Checks the size. */
    public Box {
      if (!(size.x() > 0 && size.y() > 0 && size.z() > 0)) {
        throw new IllegalArgumentException("box size " + size + " has a length that is not > 0");
      }
    }
  }

  /**
   * A hollow pipe along a world axis, built of {@code 16} flat staves.
   *
   * @param center centre of the pipe's axis (m)
   * @param axis {@code x}, {@code y} or {@code z}
   * @param innerRadius radius of the free space inside (m)
   * @param wall thickness of the wall (m)
   * @param length length along the axis (m)
   */
  record Pipe(Vec3 center, char axis, double innerRadius, double wall, double length)
      implements Obstacle {
    /** Checks the axis and the sizes. */
    public Pipe {
      if (axis != 'x' && axis != 'y' && axis != 'z') {
        throw new IllegalArgumentException("pipe axis '" + axis + "' is not x, y or z");
      }
      if (!(innerRadius > 0 && wall > 0 && length > 0)) {
        throw new IllegalArgumentException(
            "pipe innerRadius "
                + innerRadius
                + ", wall "
                + wall
                + ", length "
                + length
                + ": each must be > 0");
      }
    }
  }
}
