package org.armgals.maam.sim;

import org.ode4j.ode.DFixedJoint;
import org.ode4j.ode.DJoint.DJointFeedback;
import org.ode4j.ode.OdeHelper;

/** Two bound leg tips: a fixed joint whose feedback tells the force it carries. */
final class Binding {

  final LegModel a;
  final LegModel b;
  private final DFixedJoint joint;
  private final DJointFeedback feedback = new DJointFeedback();

  Binding(Physics physics, LegModel a, LegModel b) {
    this.a = a;
    this.b = b;
    joint = OdeHelper.createFixedJoint(physics.world);
    joint.attach(a.body, b.body);
    joint.setFixed();
    joint.setFeedback(feedback);
    a.binding = this;
    b.binding = this;
  }

  /**
   * The force the binding carried in the last physics step (N); the engine fills in the second
   * body's side.
   */
  double force() {
    return feedback.f2.length();
  }

  LegModel other(LegModel leg) {
    return leg == a ? b : a;
  }

  void release() {
    joint.destroy();
    a.binding = null;
    b.binding = null;
  }
}
