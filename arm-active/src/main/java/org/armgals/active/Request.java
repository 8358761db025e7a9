package org.armgals.active;

/**
 * A data event that asks for an answer: sent with {@link ActiveRef#ask}, answered by the receiver's
 * {@link EventProcessor#answer}, whose result completes the sender's {@link FutureValue}. Unlike a
 * {@link SynchronizedMethodRequest}, a request is data, not code, so it crosses runtimes: its
 * answer comes back on the {@code active/Future} topic (paper §4.1).
 *
 * @param <R> the type of the answer
 */
public interface Request<R> extends Event {}
