#pragma once
// The strain rule's test sheet (Tests/Unit/AdaptiveSubstepsTest.cpp,
// Tests/Gpu/GpuAdaptiveSubstepsTest.cpp): 40 x 40 vertices, 1.2 m, hung
// by `pins` (by default two opposite corners, a diagonal), and how many
// cloth sub-steps a step ran, a redo's discarded rounds included.
#include <string>

#include "Simulation/Simulation.h"

namespace soak::test {

inline std::string hungSheetScene(const std::string& simulationAttributes, const std::string& pins = "u0v0 u1v1",
                                  const std::string& clothAttributes = "") {
  return "<Scene><Simulation " + simulationAttributes +
         "/><Cloth origin='-0.6 1.9 0' axisU='1 0 0' axisV='0 -1 0' width='1.2' height='1.2' cellsU='39' "
         "cellsV='39' pinCorners='" + pins + "' " + clothAttributes + "/></Scene>";
}

// The sub-steps behind `phases` constraint phases (Simulation::clothPhasesTaken).
inline long long substepsRun(const Simulation& sim, long long phases) {
  return phases / sim.cloth.constraintPhasesPerStep(sim.settings.clothIterations, 1);
}

}  // namespace soak::test
