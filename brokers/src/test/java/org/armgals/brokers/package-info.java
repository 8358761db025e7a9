/**
 * Tests against real Apache Artemis brokers run as processes of their own: the harness that
 * creates, starts, restarts and stops standalone brokers and two-broker clusters from the broker
 * distribution, and the tests that use it. Everything here is test code; nothing is published.
 */
@NullMarked
package org.armgals.brokers;

import org.jspecify.annotations.NullMarked;
