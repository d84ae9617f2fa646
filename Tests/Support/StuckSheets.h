#pragma once
// Wet sticking's test sheets (Tests/Unit/WetClothMechanicsTest.cpp,
// Tests/Gpu/GpuWetClothTest.cpp): two damp sheets (S^T) 2 cm apart, 1.5 cm
// thick, pinned at their corners under almost no gravity, for 0.3 s; the
// worst stretch p99 of either after any step, and the closest their
// centres came.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Support/TestScenes.h"

namespace soak::test {

struct StuckSheets {
  double worstStretchP99 = 0.0;
  float closestGap = 1e9f;
};

inline StuckSheets stickTwoSheets(Device device, const std::string& pluginDir, const std::string& form,
                                  float stickiness, float timeStep) {
  TestRegistry reg(pluginDir);
  auto sim = makeSimulation(
      "<Scene><Simulation gravity='0 -0.000001 0' timeStep='" + std::to_string(timeStep) + "'/>" +
          "<Cloth name='lower' origin='-0.2 0.5 -0.2' axisU='1 0 0' axisV='0 0 1' width='0.4' height='0.4' "
          "cellsU='20' cellsV='20' pinCorners='u0v0 u1v0 u0v1 u1v1' thickness='0.015'/>"
          "<Cloth name='upper' origin='-0.2 0.52 -0.2' axisU='1 0 0' axisV='0 0 1' width='0.4' height='0.4' "
          "cellsU='20' cellsV='20' pinCorners='u0v0 u1v0 u0v1 u1v1' thickness='0.015'/>"
          "<WetCloth initialSaturation='0.12' emission='false' diffusionIterations='0' stickiness='" +
          std::to_string(stickiness) + "' stickingForm='" + form + "'/></Scene>",
      device, reg);
  StuckSheets o;
  const int steps = int(std::lround(0.3 / timeStep));
  for (int s = 0; s < steps; ++s) {
    sim->step();
    const std::vector<ClothStrain> strain = sim->cloth.strain(
        sim->particles.downloadPositions(),
        sim->cloth.vertexSlots(sim->particles.downloadIds(), sim->particles.downloadPhases()));
    for (const ClothStrain& c : strain) o.worstStretchP99 = std::max(o.worstStretchP99, c.stretchP99);
    const std::vector<Vec3> lower = sim->cloth.downloadVertexPositions(sim->particles, 0);
    const std::vector<Vec3> upper = sim->cloth.downloadVertexPositions(sim->particles, 1);
    o.closestGap = std::min(o.closestGap, upper[220].y - lower[220].y);  // the centre vertex (10, 10) of both
  }
  return o;
}

}  // namespace soak::test
