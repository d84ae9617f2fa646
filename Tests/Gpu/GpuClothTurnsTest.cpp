// The cloth constraints in turns (Base/Turns.h): on the GPU no barrier
// separates the colours; each constraint waits for the constraints before it
// on its own vertices. Each vertex then sees the same projections in the
// same order as with a barrier after every colour, so the bits must be the
// barrier schedule's, and every counter must end where the turns say.
#include <gtest/gtest.h>

#include <cstring>

#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuClothTurns, TurnsGiveTheBarriersBitsOnTheGpu) {
  SOAK_SKIP_WITHOUT_GPU();
  // One solve of 10 iterations a step, and 4 sub-steps of 6; the larger sheet
  // has as many vertices as the paper's (14.4k), so its phases spread over
  // many blocks, with tethers to two pinned corners.
  for (const char* solver : {"clothIterations='10'", "clothIterations='6' clothSubsteps='4'"})
    for (int cells : {16, 119}) {
      const std::string xml = std::string("<Scene><Simulation ") + solver +
                              "/><Cloth origin='-0.3 0.7 -0.3' width='0.6' height='0.6' cellsU='" +
                              std::to_string(cells) + "' cellsV='" + std::to_string(cells) +
                              "' pinCorners='u0v0 u1v0'/><Sphere center='0 0.45 0.05' radius='0.12'/></Scene>";
      test::TestRegistry r1, r2;
      auto turns = test::makeSimulation(xml, Device::Cuda, r1);
      auto barriers = test::makeSimulation(xml, Device::Cuda, r2);
      barriers->cloth.scheduleInTurns(false);
      ASSERT_TRUE(turns->cloth.inTurns());
      const std::vector<Float4> start = turns->particles.downloadPositions();
      for (int s = 0; s < 25; ++s) {
        turns->step();
        barriers->step();
      }
      const std::vector<Float4> a = turns->particles.downloadPositions(), b = barriers->particles.downloadPositions();
      ASSERT_EQ(a.size(), b.size());
      int differ = 0;
      float moved = 0.f;
      for (std::size_t i = 0; i < a.size(); ++i) {
        differ += std::memcmp(&a[i], &b[i], sizeof(Float4)) != 0;
        moved = std::max(moved, length(a[i].xyz() - start[i].xyz()));
      }
      EXPECT_EQ(differ, 0) << solver << ", " << cells << " cells: particles whose bits differ";
      EXPECT_GT(moved, 0.05f) << solver << ", " << cells << " cells";
      const int rounds = std::string(solver).find("Substeps") != std::string::npos ? 6 : 10;
      const std::vector<int> progress = turns->cloth.downloadVertexProgress();
      int wrong = 0;
      for (int value : progress) wrong += value != rounds * kTurnsPerRound;
      EXPECT_EQ(wrong, 0) << solver << ", " << cells << " cells: counters not at the end of the last round";
    }
}
