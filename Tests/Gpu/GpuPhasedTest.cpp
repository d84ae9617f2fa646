// The coloured cloth solve (Backend/ForEachPhased.h) has two GPU kernels: a
// thread-block cluster with the positions in its shared memory, and a
// cooperative kernel over the whole GPU with them in global memory. Within a
// phase the constraints touch disjoint vertices and between phases the order
// is fixed, so both must give the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "Backend/ForEachPhased.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

// Runs `steps` steps of xml on the GPU with the given cluster policy
// (PhasedLaunchPolicy::clusterBlocks) and returns the positions by slot: the
// slot order is the same in two runs as long as their results are.
std::vector<Float4> runWithPolicy(const std::string& xml, int steps, int clusterBlocks, int* usedBlocks) {
  phasedLaunchPolicy().clusterBlocks = clusterBlocks;
  test::TestRegistry registry;
  auto sim = test::makeSimulation(xml, Device::Cuda, registry);
  for (int s = 0; s < steps; ++s) sim->step();
  *usedBlocks = phasedLaunchPolicy().lastClusterBlocks;
  phasedLaunchPolicy().clusterBlocks = -1;
  return sim->particles.downloadPositions();
}

}  // namespace

TEST(GpuPhased, ClusterAndCooperativeKernelsGiveTheSameCloth) {
  SOAK_SKIP_WITHOUT_GPU();
  const std::string description = cudaDeviceDescription();
  // A sheet with tethers (pinned corners), sub-steps, a collider and water on it.
  const std::string xml =
      "<Scene><Simulation clothSubsteps='4' clothIterations='6'/><Sphere center='0 0.3 0' radius='0.15' "
      "friction='0.4'/><Cloth origin='-0.3 0.5 -0.3' axisU='1 0 0' axisV='0 0 1' width='0.6' height='0.6' "
      "cellsU='40' cellsV='40' pinCorners='u0v0 u1v1'/><WaterBlock min='-0.1 0.53 -0.1' max='0.1 0.63 "
      "0.1'/></Scene>";
  int gridBlocks = -1, clusterBlocks = -1;
  const std::vector<Float4> grid = runWithPolicy(xml, 30, 0, &gridBlocks);
  const std::vector<Float4> cluster = runWithPolicy(xml, 30, -1, &clusterBlocks);
  std::printf("%s: cooperative run used %d cluster blocks, cluster run %d\n", description.c_str(), gridBlocks,
              clusterBlocks);
  EXPECT_EQ(gridBlocks, 0);
  if (clusterBlocks == 0) GTEST_SKIP() << "this GPU runs no thread-block cluster (needs sm_90)";
  ASSERT_EQ(grid.size(), cluster.size());
  int differing = 0;
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (std::memcmp(&grid[i], &cluster[i], sizeof(Float4)) != 0) ++differing;
  EXPECT_EQ(differing, 0) << "of " << grid.size() << " particles";
  // The runs did something: the sheet (at y = 0.5) has draped over the ball.
  float lowest = 1e30f;
  for (const Float4& x : grid) lowest = std::min(lowest, x.y);
  EXPECT_LT(lowest, 0.4f);
}
