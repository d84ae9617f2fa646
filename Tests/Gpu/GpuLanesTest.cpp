// Lane groups (Base/Lanes.h): on the GPU several threads share an item's
// loop and combine their partial sums; the results must be those of one
// thread per item (the CPU), up to float rounding of the sums.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Backend/ForEach.h"
#include "Cloth/ClothNeighbours.h"
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
