#pragma once
// Helpers of the WetCloth tests (WetClothTest.cpp, WetClothMechanicsTest.cpp).
#include <memory>
#include <string>
#include <vector>

#include "Support/TestScenes.h"

namespace soak::test {

inline std::unique_ptr<Simulation> wetScene(const std::string& body, TestRegistry& reg,
                                            const std::vector<std::string>& overrides = {}) {
  return makeSimulation("<Scene>\n" + body + "\n</Scene>", Device::Cpu, reg, overrides);
}

// A particle channel by name (a CPU run), with a failed expectation if absent.
inline std::vector<float> channel(Simulation& sim, const std::string& name) {
  const int c = sim.particles.findChannel(name);
  EXPECT_GE(c, 0) << name;
  return c >= 0 ? sim.particles.downloadChannel(c) : std::vector<float>();
}

// A still sheet: gravity 1e-6 m/s^2 gives the gravity terms their
// direction without moving anything.
inline constexpr const char* kStill = "<Simulation gravity='0 -0.000001 0'/>";

}  // namespace soak::test
