// Minimal physics: prediction under gravity and collider projection.
#include <gtest/gtest.h>

#include <cmath>

#include "Support/TestScenes.h"

using namespace soak;

namespace {
std::unique_ptr<Simulation> scene(const std::string& body, test::TestRegistry& reg) {
  return test::makeSimulation("<Scene>\n" + body + "\n</Scene>", Device::Cpu, reg);
}
}  // namespace

TEST(Integrate, FreeFallMatchesSymplecticEuler) {
  test::TestRegistry reg;
  auto sim = scene("<Simulation timeStep=\"0.01\" gravity=\"0 -10 0\"/>"
                   "<WaterBlock min=\"0 1 0\" max=\"0.02 1.02 0.02\" velocity=\"1 2 0\"/>",
                   reg);
  ASSERT_EQ(sim->particles.count(), 1);
  const Vec3 x0 = sim->particles.downloadPositions()[0].xyz();
  const int n = 50;
  for (int k = 0; k < n; ++k) sim->step();
  const Vec3 x = sim->particles.downloadPositions()[0].xyz();
  const Vec3 v = sim->particles.downloadVelocities()[0];
  // Symplectic Euler: v_n = v0 + n g dt ; x_n = x0 + n v0 dt + g dt^2 n(n+1)/2.
  const double dt = 0.01, g = -10.0;
  EXPECT_NEAR(v.y, 2.0 + n * g * dt, 5e-4);  // v = (x* - x)/dt in float
  EXPECT_NEAR(x.y, x0.y + n * 2.0 * dt + g * dt * dt * n * (n + 1) / 2.0, 1e-4);
  EXPECT_NEAR(x.x, x0.x + n * 1.0 * dt, 1e-4);
}

TEST(Integrate, ParticlesComeToRestOnPlane) {
  test::TestRegistry reg;
  // Spacing above h: the particles do not interact, only the plane acts.
  auto sim = scene("<Water spacing=\"0.05\"/><Plane point=\"0 0 0\" normal=\"0 1 0\" friction=\"0.5\"/>"
                   "<WaterBlock min=\"0 0.2 0\" max=\"0.1 0.3 0.1\"/>",
                   reg);
  const int count = sim->particles.count();
  for (int k = 0; k < 200; ++k) sim->step();
  // None lost: a particle that went NaN would be drained as "outside the
  // domain", and the checks below would pass over the ones left.
  ASSERT_EQ(sim->particles.count(), count);
  const float r = 0.25f * sim->water.supportRadius;
  for (const Float4& p : sim->particles.downloadPositions()) EXPECT_NEAR(p.y, r, 1e-5);
  for (const Vec3& v : sim->particles.downloadVelocities()) EXPECT_LT(length(v), 1e-3f);
}

TEST(Integrate, BoxContainerKeepsParticlesInside) {
  test::TestRegistry reg;
  auto sim = scene("<Box min=\"-0.2 0 -0.2\" max=\"0.2 1 0.2\" inside=\"true\" friction=\"0\"/>"
                   "<WaterBlock min=\"-0.1 0.3 -0.1\" max=\"0.1 0.4 0.1\" velocity=\"3 0 -2\"/>",
                   reg);
  const float r = 0.25f * sim->water.supportRadius;
  for (int k = 0; k < 300; ++k) {
    sim->step();
    for (const Float4& p : sim->particles.downloadPositions()) {
      ASSERT_GE(p.x, -0.2f + r - 1e-5f);
      ASSERT_LE(p.x, 0.2f - r + 1e-5f);
      ASSERT_GE(p.y, r - 1e-5f);
      ASSERT_GE(p.z, -0.2f + r - 1e-5f);
    }
  }
}

TEST(Integrate, SphereDeflectsFallingParticles) {
  test::TestRegistry reg;
  auto sim = scene("<Water spacing=\"0.05\"/><Sphere center=\"0 0 0\" radius=\"0.3\" friction=\"0\"/>"
                   "<WaterBlock min=\"0.05 0.5 -0.05\" max=\"0.15 0.6 0.05\"/>",
                   reg);
  const float r = 0.25f * sim->water.supportRadius;
  float minDist = 1e9f;
  for (int k = 0; k < 150; ++k) {
    sim->step();
    for (const Float4& p : sim->particles.downloadPositions()) minDist = std::min(minDist, length(p.xyz()));
  }
  EXPECT_GE(minDist, 0.3f + r - 1e-4f);
  // They slid off the ball to +x (they started right of the top).
  for (const Float4& p : sim->particles.downloadPositions()) EXPECT_GT(p.x, 0.15f);
}

TEST(Integrate, FrictionSlowsSliding) {
  auto slideDistance = [](const char* friction) {
    test::TestRegistry reg;
    auto sim = scene(std::string("<Plane friction=\"") + friction +
                         "\"/><WaterBlock min=\"0 0 0\" max=\"0.02 0.02 0.02\" velocity=\"2 0 0\"/>",
                     reg);
    for (int k = 0; k < 40; ++k) sim->step();
    return sim->particles.downloadPositions()[0].x;
  };
  EXPECT_GT(slideDistance("0"), 1.0f);   // frictionless: 2 m/s for 0.6 s
  EXPECT_LT(slideDistance("0.5"), 0.1f);
}

TEST(Integrate, PinnedParticlesDoNotMove) {
  ParticleState ps(Device::Cpu);
  ParticleInit p;
  p.position = Vec3(0, 1, 0);
  p.mass = 1.f;
  p.radius = 0.04f;
  p.pinned = true;
  ps.append({p});
  Simulation sim(Device::Cpu);
  sim.particles.append({p});
  sim.initialize();
  for (int k = 0; k < 10; ++k) sim.step();
  EXPECT_EQ(sim.particles.downloadPositions()[0].y, 1.f);
}
