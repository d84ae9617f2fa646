// Lane groups (Base/Lanes.h): on the GPU several threads share an item's
// loop and combine their partial sums; the results must be those of one
// thread per item (the CPU), up to float rounding of the sums.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Backend/ForEach.h"
#include "Cloth/ClothNeighbours.h"
#include "Coupling/TriangleCoupling.h"
#include "Particles/Phase.h"
#include "LaneSums.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuLanes, ListSumsMatchOneThreadPerItem) {
  SOAK_SKIP_WITHOUT_GPU();
  // Sizes that give 16, 8, 4, 2 and 1 lanes; list lengths 0-70 (fluid lists hold about 50).
  for (int n : {700, 130000, 300000, 600000, 1200000}) {
    std::mt19937 rng(1234u + unsigned(n));
    std::uniform_int_distribution<int> length(0, 70);
    std::uniform_real_distribution<float> value(-1.f, 1.f);
    std::vector<int> start(1, 0);
    std::vector<float> values;
    for (int i = 0; i < n; ++i) {
      const int len = (i % 97 == 0) ? 0 : length(rng);
      for (int k = 0; k < len; ++k) values.push_back(value(rng));
      start.push_back(int(values.size()));
    }
    const float threshold = 0.995f;  // most items have no entry above it
    const test::ListSums cpu = test::laneListSums(Device::Cpu, start, values, threshold);
    const test::ListSums gpu = test::laneListSums(Device::Cuda, start, values, threshold);
    ASSERT_EQ(gpu.sum.size(), std::size_t(n));
    int mismatched = 0, withAny = 0;
    for (int i = 0; i < n; ++i) {
      double bound = 0.0;
      for (int k = start[i]; k < start[i + 1]; ++k) bound += std::fabs(values[k]);
      if (std::fabs(double(gpu.sum[i]) - double(cpu.sum[i])) > 1e-6 * bound + 1e-7) ++mismatched;
      if (gpu.count[i] != cpu.count[i] || gpu.any[i] != cpu.any[i]) ++mismatched;
      withAny += cpu.any[i];
    }
    EXPECT_EQ(mismatched, 0) << n << " items, " << lanesFor(n) << " lanes";
    EXPECT_GT(withAny, 0);
    EXPECT_LT(withAny, n);
  }
}

TEST(GpuLanes, ClothListsBuiltWithLaneGroupsKeepTheGridsOrder) {
  SOAK_SKIP_WITHOUT_GPU();
  // Lists built by groups of lanes rank each round's kept candidates with a
  // ballot: they must be the lists one thread per item builds, entry for entry.
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Cloth origin='-0.2 0.6 -0.2' width='0.4' height='0.4' cellsU='40' cellsV='40'/>"
      "<Sphere center='0 0.3 0' radius='0.1'/></Scene>",
      Device::Cuda, reg);
  for (int s = 0; s < 40; ++s) sim->step();
  const ParticleView p = sim->particles.view();
  const ClothView c = sim->cloth.view();
  ClothNeighbours grouped(Device::Cuda), single(Device::Cuda);
  grouped.build(p, sim->cloth.grid(), clothSlots(c), c.thickness, true, true);
  single.build(p, sim->cloth.grid(), clothSlots(c), c.thickness, true, false);
  const auto a = grouped.download(), b = single.download();
  ASSERT_EQ(a.size(), std::size_t(c.vertexCount));
  ASSERT_EQ(a.size(), b.size());
  std::size_t entries = 0;
  for (std::size_t v = 0; v < a.size(); ++v) {
    EXPECT_EQ(a[v], b[v]) << "cloth particle " << v;
    entries += b[v].size();
  }
  std::printf("%d cloth particles, %d lanes, %.1f entries each\n", c.vertexCount, lanesFor(c.vertexCount),
              double(entries) / double(a.size()));
  EXPECT_GT(entries, 20 * a.size());
}

TEST(GpuLanes, CouplingRoundsMoveTheWaterAsTheOneLaneWalkDoes) {
  SOAK_SKIP_WITHOUT_GPU();
  // The coupling's rounds (TriangleCoupling.cpp) take a path box's cells a
  // group at a time and its entries in rounds across cells; they must
  // apply the one-lane walk's corrections in its order, so every group
  // size leaves the same bits. Water resting on a pinned sheet, each water
  // particle's predicted position pushed 3 cm down through the sheet.
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Cloth origin='-0.3 0.5 -0.3' axisU='1 0 0' axisV='0 0 1' width='0.6' height='0.6' cellsU='30' "
      "cellsV='30' pinCorners='u0v0 u1v0 u0v1 u1v1'/><WaterBlock min='-0.1 0.53 -0.1' max='0.1 0.63 0.1'/></Scene>",
      Device::Cuda, reg);
  for (int s = 0; s < 10; ++s) sim->step();
  const ParticleView p = sim->particles.view();
  const std::vector<Float4> position = sim->particles.downloadPositions();
  const std::vector<int> phase = sim->particles.downloadPhases();
  std::vector<Float4> pushed = position;
  int water = 0;
  for (std::size_t i = 0; i < pushed.size(); ++i)
    if (isWater(phase[i])) {
      pushed[i].y -= 0.03f;
      ++water;
    }
  ASSERT_GE(water, 400);
  Buffer<int> moved(Device::Cuda, std::size_t(p.count));
  std::vector<std::vector<Float4>> after;
  for (int lanes : {1, 2, 4, 8, 16}) {
    copyHostToDevice(Device::Cuda, p.predicted, pushed.data(), pushed.size() * sizeof(Float4));
    projectWaterOutOfCloth(Device::Cuda, p, sim->cloth.grid(), sim->cloth.view(), nullptr, 2, moved.data(), 1, lanes);
    after.push_back(sim->particles.downloadPredicted());
  }
  int corrected = 0;
  for (std::size_t i = 0; i < pushed.size(); ++i) {
    const Float4 one = after[0][i];
    if (one.x != pushed[i].x || one.y != pushed[i].y || one.z != pushed[i].z) ++corrected;
    for (std::size_t k = 1; k < after.size(); ++k) {
      const Float4 q = after[k][i];
      ASSERT_TRUE(q.x == one.x && q.y == one.y && q.z == one.z)
          << "slot " << i << ", " << (1 << k) << " lanes against one: (" << q.x << ", " << q.y << ", " << q.z
          << ") against (" << one.x << ", " << one.y << ", " << one.z << ")";
    }
  }
  std::printf("%d water particles, %d corrected\n", water, corrected);
  EXPECT_GT(corrected, water / 4);
}
