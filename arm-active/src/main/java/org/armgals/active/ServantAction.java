package org.armgals.active;

/**
 * A one-way request: code run by an active object on its servant.
 *
 * @param <S> the servant type
 */
@FunctionalInterface
public interface ServantAction<S> {
  /** Runs on the servant, on the object's own thread. */
  void run(S servant) throws Exception;
}
