// The template plugin's stage, tested as Soak's own tests test theirs: a
// registry with the plugin loaded, a simulation from a scene string,
// stepped on the CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "Support/TestScenes.h"

namespace {

// Mean velocity of all particles (the water's internal forces conserve it).
soak::Vec3 meanVelocity(const soak::Simulation& sim) {
  const std::vector<soak::Vec3> v = sim.particles.downloadVelocities();
  soak::Vec3 sum(0.f, 0.f, 0.f);
  for (const soak::Vec3& x : v) sum += x;
  return sum / float(v.size());
}

}  // namespace

TEST(SteadyWind, WaterInWeightlessAirReachesTheWindAtTheExactRateWhateverTheStep) {
  // v(t) = w (1 - exp(-k t)) for water starting at rest without gravity.
  const float w = 2.f, k = 3.f, t = 0.6f;
  const float expected = w * (1.f - std::exp(-k * t));
  for (const char* dt : {"0.01", "0.005"}) {
    soak::test::TestRegistry reg(PLUGIN_DIR);
    ASSERT_TRUE(reg.registry.hasPlugin("SteadyWind"));
    auto sim = soak::test::makeSimulation(std::string("<Scene><Simulation gravity='0 0 0' timeStep='") + dt +
                                              "'/><WaterBlock min='-0.05 0.5 -0.05' max='0.05 0.6 0.05'/>"
                                              "<SteadyWind velocity='2 0 0' rate='3'/></Scene>",
                                          soak::Device::Cpu, reg);
    while (sim->time() < t - 1e-6) sim->step();
    const soak::Vec3 v = meanVelocity(*sim);
    EXPECT_NEAR(v.x, expected, 2e-3f * expected) << "dt " << dt;
    EXPECT_NEAR(v.y, 0.f, 1e-3f) << "dt " << dt;
  }
}

TEST(SteadyWind, RunsBeforeThePredictStage) {
  soak::test::TestRegistry reg(PLUGIN_DIR);
  auto sim = soak::test::makeSimulation("<Scene><WaterBlock min='0 0 0' max='0.05 0.05 0.05'/><SteadyWind/></Scene>",
                                        soak::Device::Cpu, reg);
  const std::vector<std::string> names = sim->pipeline.names();
  const auto at = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
  ASSERT_LT(at("wind.relax"), long(names.size()));
  EXPECT_EQ(at("wind.relax") + 1, at("predict"));
}
