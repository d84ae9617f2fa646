// The same scene on CPU and CUDA agrees within float round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "Support/TestScenes.h"

using namespace soak;

namespace {
std::map<int, Vec3> positionsById(Simulation& sim) {
  std::map<int, Vec3> m;
  auto pos = sim.particles.downloadPositions();
  auto ids = sim.particles.downloadIds();
  auto phase = sim.particles.downloadPhases();
  // Water and cloth number their ids separately: key by phase too.
  for (std::size_t i = 0; i < pos.size(); ++i) m[ids[i] + 10000000 * phase[i]] = pos[i].xyz();
  return m;
}
}  // namespace

TEST(GpuAgreement, FallingParticlesMatchCpu) {
  SOAK_SKIP_WITHOUT_GPU();
  const std::string xml =
      "<Scene><Water spacing=\"0.05\"/><Plane friction=\"0.3\"/><Sphere center=\"0 0.3 0\" radius=\"0.2\"/>"
      "<Box min=\"-0.5 -0.1 -0.5\" max=\"0.5 2 0.5\" inside=\"true\"/>"
      "<WaterBlock min=\"-0.2 0.6 -0.2\" max=\"0.2 0.9 0.2\" velocity=\"0.5 0 0\"/></Scene>";
  test::TestRegistry regCpu, regGpu;
  auto cpu = test::makeSimulation(xml, Device::Cpu, regCpu);
  auto gpu = test::makeSimulation(xml, Device::Cuda, regGpu);
  ASSERT_EQ(cpu->particles.count(), gpu->particles.count());
  for (int s = 0; s < 60; ++s) {
    cpu->step();
    gpu->step();
  }
  auto a = positionsById(*cpu), b = positionsById(*gpu);
  ASSERT_EQ(a.size(), b.size());
  float worst = 0.f;
  for (const auto& [id, p] : a) worst = std::max(worst, length(p - b.at(id)));
  EXPECT_LT(worst, 1e-4f) << "largest CPU/GPU position difference after 60 steps (m)";
}

TEST(GpuAgreement, NeighbourCountsAndStatsMatchCpu) {
  SOAK_SKIP_WITHOUT_GPU();
  const std::string xml = "<Scene><WaterBlock min=\"0 0 0\" max=\"0.6 0.4 0.4\"/></Scene>";
  test::TestRegistry r1, r2;
  auto cpu = test::makeSimulation(xml, Device::Cpu, r1);
  auto gpu = test::makeSimulation(xml, Device::Cuda, r2);
  cpu->step();
  gpu->step();
  StatsRow sc = cpu->collectStats(), sg = gpu->collectStats();
  EXPECT_EQ(sc.get("water_particles"), sg.get("water_particles"));
  EXPECT_NEAR(sc.get("free_water_mass"), sg.get("free_water_mass"), 1e-9);
  // The grid orders particles identically (stable sort on both devices).
  EXPECT_EQ(cpu->particles.downloadIds(), gpu->particles.downloadIds());
}

TEST(GpuAgreement, WaterJetOnClothMatchesCpuOverShortRun) {
  // Dry physics (PBF, cloth, contact, Eq. 21 coupling) for 12 steps: CPU and
  // CUDA differ only by float summation order, which grows slowly.
  SOAK_SKIP_WITHOUT_GPU();
  const std::string xml =
      "<Scene><Cloth origin='-0.3 0.6 0' axisU='1 0 0' axisV='0 -1 0' width='0.6' height='0.6' cellsU='24' "
      "cellsV='24' pinCorners='u0v0 u1v0'/><Nozzle position='0 0.4 0.3' direction='0 0 -1' radius='0.05' "
      "speed='4'/><Plane/></Scene>";
  test::TestRegistry regCpu, regGpu;
  auto cpu = test::makeSimulation(xml, Device::Cpu, regCpu);
  auto gpu = test::makeSimulation(xml, Device::Cuda, regGpu);
  for (int s = 0; s < 12; ++s) {
    cpu->step();
    gpu->step();
  }
  auto a = positionsById(*cpu), b = positionsById(*gpu);
  ASSERT_EQ(cpu->particles.count(), gpu->particles.count());
  float worstCloth = 0.f, worstWater = 0.f;
  auto ca = cpu->cloth.downloadVertexPositions(cpu->particles, 0);
  auto cb = gpu->cloth.downloadVertexPositions(gpu->particles, 0);
  for (std::size_t v = 0; v < ca.size(); ++v) worstCloth = std::max(worstCloth, length(ca[v] - cb[v]));
  for (const auto& [id, p] : a) worstWater = std::max(worstWater, length(p - b.at(id)));
  std::printf("CPU/GPU after 12 steps: cloth %.3g m, all particles by id %.3g m\n", worstCloth, worstWater);
  EXPECT_LT(worstCloth, 1e-3f);
  EXPECT_LT(worstWater, 1e-3f);
  double meanA, meanB;
  float maxA, maxB;
  cpu->fluid.densityError(*cpu, meanA, maxA);
  gpu->fluid.densityError(*gpu, meanB, maxB);
  EXPECT_NEAR(meanA, meanB, 1e-3);
}
