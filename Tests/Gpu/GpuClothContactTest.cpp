// Cloth contact on the GPU, where vertex-triangle contact runs its
// sequential pass by a group of lanes (Cloth/ClothContact.cpp): the folded
// sheet of the CPU test keeps its layers apart here too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "Support/FoldedSheet.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuClothContact, FoldedSheetFallingOnTheFloorDoesNotPassThroughItself) {
  SOAK_SKIP_WITHOUT_GPU();
  const test::FoldedSheet folded;
  const std::string obj = testing::TempDir() + "/folded_gpu.obj";
  folded.write(obj);
  const char* solvers[][2] = {{"", ""}, {"clothSubsteps='8' clothIterations='12'", "model='chebyshev'"}};
  for (const auto& solver : solvers) {
    test::TestRegistry reg;
    auto sim = test::makeSimulation(std::string("<Scene><Simulation ") + solver[0] + "/><Cloth name='folded' mesh='" +
                                        obj + "' bendStiffness='0' " + solver[1] +
                                        "/><Plane point='0 0 0' normal='0 1 0'/></Scene>",
                                    Device::Cuda, reg);
    float worst = 1e9f;
    for (int s = 0; s < 150; ++s) {
      sim->step();
      worst = std::min(worst, folded.smallestLayerGap(sim->cloth.downloadVertexPositions(sim->particles, 0)));
    }
    std::printf("CUDA, folded sheet (%s %s): smallest upper-minus-lower layer height %.4f m\n", solver[0], solver[1],
                worst);
    EXPECT_GT(worst, 0.005f) << solver[0] << " " << solver[1];  // as on the CPU (Tests/Unit/DryPhysicsTest.cpp)
  }
}
