package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeHelper;

class PartOrderTest {

  @Test
  void keepsTheOrderOfTheEnginesSimpleSpaceWhateverMovesAndWhenever() {
    // Physics sets the engine up (its static initializer).
    new Physics(Scenes.builtIn("single"), 1, 1).destroy();
    DWorld world = OdeHelper.createWorld();
    DBody body = OdeHelper.createBody(world);
    DSpace space = OdeHelper.createSimpleSpace();
    int count = 7;
    DGeom[] geoms = new DGeom[count];
    for (int p = 0; p < count; p++) {
      geoms[p] = OdeHelper.createSphere(space, 0.01);
      geoms[p].setBody(body);
      geoms[p].setOffsetPosition(p, 0, 0);
    }
    PartOrder order = new PartOrder(count);
    SplittableRandom random = new SplittableRandom(42);
    for (int event = 0; event < 5000; event++) {
      switch (random.nextInt(4)) {
        case 0, 1 -> {
          int p = random.nextInt(count);
          geoms[p].setOffsetPosition(random.nextDouble(), 0, 0);
          order.moved(p);
        }
        case 2 -> {
          body.setPosition(random.nextDouble(), 0, 0);
          // The body marks its geometries from the last put on it to the first.
          for (int p = count - 1; p >= 0; p--) {
            order.moved(p);
          }
        }
        default -> {
          space.cleanGeoms();
          order.clean();
        }
      }
      int i = 0;
      for (DGeom g : space.getGeoms()) {
        assertThat(geoms[order.get(i)]).as("event %d, position %d", event, i).isSameAs(g);
        i++;
      }
    }
    space.destroy();
    world.destroy();
  }
}
