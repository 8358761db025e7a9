package org.armgals.maam;

import java.util.List;

/** The names of a robot's adaptations as behaviors of its {@link RobotKind}. */
final class RobotAdaptations {
  static final String CHANGE_MODULE = "changeModule";

  static final List<String> NAMES =
      List.of(
          "setScheduling",
          "changeModule",
          "addSchema",
          "removeSchema",
          "addConnector",
          "removeConnector");

  private RobotAdaptations() {}

  static String name(Adaptation change) {
    return switch (change) {
      case Adaptation.SetScheduling s -> NAMES.get(0);
      case Adaptation.ChangeModule c -> NAMES.get(1);
      case Adaptation.AddSchema a -> NAMES.get(2);
      case Adaptation.RemoveSchema r -> NAMES.get(3);
      case Adaptation.AddConnector a -> NAMES.get(4);
      case Adaptation.RemoveConnector r -> NAMES.get(5);
    };
  }
}
