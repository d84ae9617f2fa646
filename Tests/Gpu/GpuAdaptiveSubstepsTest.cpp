// Cloth sub-steps from the cloth's speed on the GPU (Cloth/AdaptiveSubsteps.h):
// the travel the predict stage measures and the cloth stage reads back
// gives the step the same sub-steps as on the CPU.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuAdaptiveSubsteps, AFallingSheetTakesTheSubstepsItDoesOnTheCpu) {
  SOAK_SKIP_WITHOUT_GPU();
  // A free sheet 1 cm thick falls from rest: its speed after predict is g dt s
  // in step s, so the count climbs from 2 to the most, 16, by step 37.
  const std::string xml =
      "<Scene><Simulation clothIterations='6' clothSubsteps='2' clothSubstepTravel='0.5' clothMaxSubsteps='16'/>"
      "<Cloth model='chebyshev' thickness='0.01' origin='-0.2 2 -0.2' axisU='1 0 0' axisV='0 0 1' width='0.4' "
      "height='0.4' cellsU='9' cellsV='9'/></Scene>";
  test::TestRegistry cpuReg, gpuReg;
  auto cpu = test::makeSimulation(xml, Device::Cpu, cpuReg);
  auto gpu = test::makeSimulation(xml, Device::Cuda, gpuReg);
  int differing = 0, last = 0;
  for (int s = 1; s <= 40; ++s) {
    cpu->step();
    gpu->step();
    // A step whose travel lies within round-off of a boundary may round
    // either way; none of these does by more than one.
    EXPECT_LE(std::abs(cpu->lastClothSubsteps() - gpu->lastClothSubsteps()), 1) << "step " << s;
    differing += cpu->lastClothSubsteps() != gpu->lastClothSubsteps();
    EXPECT_GE(gpu->lastClothSubsteps(), last) << "step " << s;
    last = gpu->lastClothSubsteps();
  }
  std::printf("falling sheet, 40 steps: %d steps with another sub-step count on the GPU; last %d\n", differing, last);
  EXPECT_LE(differing, 2);
  EXPECT_EQ(last, 16);
}
