package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.armgals.representation.State;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.Test;

/** The kernel of figure 2, as ObjVlisp builds it. */
class BootstrapTest extends KernelFixture {

  @Test
  void structuralMetaIsItsOwnInstance() {
    assertThat(kernel.structuralMeta().structuralMeta()).isSameAs(kernel.structuralMeta());
    assertThat(kernel.structuralMeta().instances()).contains(kernel.structuralMeta());
  }

  @Test
  void theThreeKernelClassesAreInstancesOfStructuralMeta() {
    for (StructuralMeta<?> m :
        List.of(kernel.entity(), kernel.structuralMeta(), kernel.behavioralMeta())) {
      assertThat(m.structuralMeta()).as(m.name()).isSameAs(kernel.structuralMeta());
    }
    assertThat(kernel.structuralMeta().instances())
        .containsExactly(kernel.structuralMeta(), kernel.entity(), kernel.behavioralMeta());
  }

  @Test
  void structuralAndBehavioralMetaInheritFromEntityWhichInheritsFromNothing() {
    assertThat(kernel.structuralMeta().superMeta()).containsSame(kernel.entity());
    assertThat(kernel.behavioralMeta().superMeta()).containsSame(kernel.entity());
    assertThat(kernel.entity().superMeta()).isEmpty();
  }

  @Test
  void
      basicBehavioralMetaIsAnInstanceOfBehavioralMetaAndTheMetaOfAllKernelEntitiesItselfIncluded() {
    BehavioralMeta basic = kernel.basicBehavioralMeta();
    assertThat(basic.structuralMeta()).isSameAs(kernel.behavioralMeta());
    assertThat(kernel.behavioralMeta().instances()).containsExactly(basic);
    for (Entity e :
        List.of(kernel.entity(), kernel.structuralMeta(), kernel.behavioralMeta(), basic)) {
      assertThat(e.behavioralMeta()).as(e.name()).containsSame(basic);
    }
    assertThat(basic.baseLevelEntities())
        .containsExactlyInAnyOrder(
            kernel.entity(), kernel.structuralMeta(), kernel.behavioralMeta(), basic);
  }

  @Test
  void userKindsAreMadeTheWayTheKernelMadeItsOwn() {
    StructuralMeta<PState> robot = robotKind();
    Entity r1 = robot.newEntity("r1", kernel.basicBehavioralMeta());

    assertThat(robot.structuralMeta()).isSameAs(kernel.structuralMeta());
    assertThat(robot.superMeta()).containsSame(kernel.entity());
    assertThat(robot.behavioralMeta()).containsSame(kernel.basicBehavioralMeta());
    assertThat(kernel.structuralMeta().instances()).contains(robot);
    assertThat(r1.structuralMeta()).isSameAs(robot);
    assertThat(robot.instances()).containsExactly(r1);
    assertThat(r1.state()).isEqualTo(robot.getInitialState());

    BehavioralMeta watcher = kernel.newBehavioralMeta("watcher", new Recorder(), Damping.none());
    assertThat(watcher.structuralMeta()).isSameAs(kernel.behavioralMeta());
    assertThat(watcher.behavioralMeta()).containsSame(kernel.basicBehavioralMeta());
    assertThat(kernel.lookupEntity("watcher")).containsSame(watcher);
    assertThat(kernel.lookupEntity(r1.address())).containsSame(r1);
  }

  @Test
  void basicBehavioralMetaModelsTheKernelFromItsOwnActionEvents() {
    StructuralMeta<PState> robot = robotKind();
    drain(kernel.structuralMeta());
    State model = kernel.basicBehavioralMeta().model(kernel.structuralMeta()).getValue().state();

    assertThat(model).isEqualTo(kernel.structuralMeta().state());
    assertThat(model.observe().get("instances"))
        .isEqualTo(List.of("StructuralMeta", "Entity", "BehavioralMeta", robot.name()));
  }

  @Test
  void metaEntitiesAreMadeOnlyThroughTheKernel() {
    assertThatThrownBy(() -> kernel.structuralMeta().newEntity("x", kernel.basicBehavioralMeta()))
        .isInstanceOf(UnsupportedOperationException.class)
        .hasMessageContaining("Kernel.newStructuralMeta");
  }

  @Test
  void aTakenNameIsRefusedWithTheName() {
    robotKind();
    assertThatThrownBy(() -> robotKind())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'Robot'");
  }
}
