// Instability detection (Simulation/Instability.h): non-finite values and
// runaway speed are found and named; non-finite water is not drained.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "Simulation/Instability.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {
const char* kBlock =
    "<Scene><Simulation maxSpeed='50'/><WaterBlock min='0 0.5 0' max='0.1 0.6 0.1'/><Plane/></Scene>";
}

TEST(Instability, SoundStateIsNotReported) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(kBlock, Device::Cpu, reg);
  Buffer<float> scratch(Device::Cpu);
  for (int s = 0; s < 5; ++s) sim->step();
  EXPECT_FALSE(findInstability(*sim, scratch).found);
}

TEST(Instability, RunawayAndNonFiniteParticlesAreNamed) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(kBlock, Device::Cpu, reg);
  Buffer<float> scratch(Device::Cpu);
  sim->step();
  ParticleView p = sim->particles.view();  // CPU memory: written directly
  const int k = p.count / 2;
  p.velocity[k] = Vec3(0.f, 60.f, 0.f);
  Instability fast = findInstability(*sim, scratch);
  ASSERT_TRUE(fast.found);
  EXPECT_TRUE(fast.finite);
  EXPECT_EQ(fast.id, p.id[k]);
  EXPECT_NEAR(fast.speed, 60.f, 1e-4f);
  EXPECT_NE(describeInstability(fast, 50.f).find("moves at 60 m/s, above Simulation.maxSpeed = 50 m/s"),
            std::string::npos)
      << describeInstability(fast, 50.f);
  // A NaN elsewhere is worse than a fast particle: it is the one reported.
  const int j = p.count / 3;
  p.velocity[j].x = std::numeric_limits<float>::quiet_NaN();
  Instability nan = findInstability(*sim, scratch);
  ASSERT_TRUE(nan.found);
  EXPECT_FALSE(nan.finite);
  EXPECT_EQ(nan.id, p.id[j]);
}

TEST(Instability, NonFiniteWaterIsNotDrainedAndStageCheckNamesTheStage) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(kBlock, Device::Cpu, reg);
  sim->step();
  const int before = sim->particles.count();
  ParticleView p = sim->particles.view();
  const int id = p.id[0];
  p.position[0] = Float4(Vec3(std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.f), p.position[0].w);
  sim->checkStages = true;
  try {
    sim->step();
    FAIL() << "no instability reported";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.instability.stage, "predict") << e.what();
    EXPECT_EQ(e.instability.id, id);
    EXPECT_FALSE(e.instability.finite);
  }
  // The drain (after predict) did not run in that step; run one without
  // stage checks: the NaN particle must still be there, not counted as drained.
  sim->checkStages = false;
  sim->step();
  EXPECT_EQ(sim->particles.count(), before);
  EXPECT_EQ(sim->drainedWaterMass, 0.0);
}
