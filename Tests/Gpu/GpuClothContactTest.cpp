// Cloth contact on the GPU, where vertex-triangle contact runs its
// sequential pass by a group of lanes (Cloth/ClothContact.cpp): the folded
// sheet of the CPU test keeps its layers apart here too.
#include <gtest/gtest.h>

#include <cstdio>

#include "Support/FoldedSheet.h"
#include "Support/TempFiles.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuClothContact, FoldedSheetFallingOnTheFloorDoesNotPassThroughItself) {
  SOAK_SKIP_WITHOUT_GPU();
  const char* solvers[][2] = {{"", "model='pbd'"}, {"clothSubsteps='8' clothIterations='12'", "model='chebyshev'"}};
  for (const auto& solver : solvers) {
    const float worst = test::FoldedSheet{}.smallestGapWhenDropped(Device::Cuda, test::processTempPath("folded_gpu.obj"),
                                                                   solver[0], solver[1]);
    std::printf("CUDA, folded sheet (%s %s): smallest upper-minus-lower layer height %.4f m\n", solver[0], solver[1],
                worst);
    EXPECT_GT(worst, 0.005f) << solver[0] << " " << solver[1];  // as on the CPU (Tests/Unit/DryPhysicsTest.cpp)
  }
}
