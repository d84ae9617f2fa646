// Cloth sub-steps from the cloth's speed on the GPU (Cloth/AdaptiveSubsteps.h):
// the travel the predict stage measures gives the step the same sub-steps
// as on the CPU, chosen and run on the device (Cloth/SubstepClock.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "Backend/Device.h"

#include "Support/HungSheet.h"
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

TEST(GpuAdaptiveSubsteps, InAStepGraphTheSubstepsAreChosenAndRunWithoutAHostWait) {
  SOAK_SKIP_WITHOUT_GPU();
  // The falling sheet again, with step graphs (the count is chosen on the
  // device and the sub-steps run as a graph's loop node) and without (the
  // host reads the count and queues each sub-step): the same counts, the
  // same sheet, and no host wait in a plain step with graphs.
  const std::string scene =
      "<Scene><Simulation clothIterations='6' clothSubsteps='2' clothSubstepTravel='0.5' clothMaxSubsteps='16' "
      "cudaGraph='GRAPH'/>"
      "<Cloth model='chebyshev' thickness='0.01' origin='-0.2 2 -0.2' axisU='1 0 0' axisV='0 0 1' width='0.4' "
      "height='0.4' cellsU='9' cellsV='9'/></Scene>";
  auto with = [&](const char* graph) {
    std::string xml = scene;
    xml.replace(xml.find("GRAPH"), 5, graph);
    return xml;
  };
  test::TestRegistry graphReg, plainReg;
  auto graphs = test::makeSimulation(with("true"), Device::Cuda, graphReg);
  auto plain = test::makeSimulation(with("false"), Device::Cuda, plainReg);
  int waitingSteps = 0, differing = 0, most = 0;
  for (int s = 1; s <= 40; ++s) {
    const bool maintenance = graphs->maintenanceStep();
    const unsigned long long before = hostWaits();
    graphs->step();
    if (!maintenance && hostWaits() != before) ++waitingSteps;
    plain->step();
    EXPECT_LE(std::abs(graphs->lastClothSubsteps() - plain->lastClothSubsteps()), 1) << "step " << s;
    differing += graphs->lastClothSubsteps() != plain->lastClothSubsteps();
    most = std::max(most, graphs->lastClothSubsteps());
  }
  const std::vector<Vec3> a = graphs->cloth.downloadVertexPositions(graphs->particles, 0);
  const std::vector<Vec3> b = plain->cloth.downloadVertexPositions(plain->particles, 0);
  ASSERT_EQ(a.size(), b.size());
  float worst = 0.f;
  for (std::size_t v = 0; v < a.size(); ++v) worst = std::max(worst, length(a[v] - b[v]));
  std::printf("falling sheet with and without step graphs, 40 steps: %d plain steps waited, %d counts differ, "
              "most %d sub-steps, vertices %.3g m apart at most\n",
              waitingSteps, differing, most, double(worst));
  EXPECT_EQ(waitingSteps, 0);
  EXPECT_EQ(most, 16);
  EXPECT_LE(differing, 2);
  EXPECT_LT(worst, 1e-4f);  // the sheet fell about 0.5 m; cell 4.4 cm
}

TEST(GpuAdaptiveSubsteps, TheStrainRedoRunsInTheStepGraphAndHoldsTheSheetAsOnTheCpu) {
  SOAK_SKIP_WITHOUT_GPU();
  // The sheet of AdaptiveSubsteps.TheStrainRedoKeepsAFallingSheetUnder...
  // (40 x 40, 1.2 m, hung by a diagonal), let go with the strain rule from
  // 2 sub-steps: its first swing passes 3 % p99 without the redo (CPU). On
  // the GPU the redo's check and its second round of sub-steps run inside
  // the step graph's loop node, with no host wait, and hold the sheet as
  // on the CPU.
  const std::string xml =
      test::hungSheetScene("clothSubsteps='2' clothIterations='12' clothSubstepTravel='0.5' clothStrainTarget='0.02'");
  test::TestRegistry cpuReg, gpuReg;
  auto cpu = test::makeSimulation(xml, Device::Cpu, cpuReg);
  auto gpu = test::makeSimulation(xml, Device::Cuda, gpuReg);
  int waitingSteps = 0, cpuMost = 0, gpuMost = 0, redone = 0;
  double cpuWorst = 0.0, gpuWorst = 0.0;
  for (int s = 1; s <= 67; ++s) {
    cpu->step();
    const bool maintenance = gpu->maintenanceStep();
    const long long phasesBefore = gpu->clothPhasesTaken();
    const unsigned long long before = hostWaits();
    gpu->step();
    if (!maintenance && hostWaits() != before) ++waitingSteps;
    redone += test::substepsRun(*gpu, gpu->clothPhasesTaken() - phasesBefore) > gpu->lastClothSubsteps();
    cpuWorst = std::max(cpuWorst, cpu->collectStats().get("strain_p99_cloth"));
    gpuWorst = std::max(gpuWorst, gpu->collectStats().get("strain_p99_cloth"));
    cpuMost = std::max(cpuMost, cpu->lastClothSubsteps());
    gpuMost = std::max(gpuMost, gpu->lastClothSubsteps());
  }
  std::printf("sheet hung by a diagonal from 2 sub-steps with the strain redo, 1 s: CPU p99 %.2f %% (most %d "
              "sub-steps), GPU %.2f %% (most %d, %d steps redone), %d plain GPU steps waited\n",
              100 * cpuWorst, cpuMost, 100 * gpuWorst, gpuMost, redone, waitingSteps);
  EXPECT_GT(redone, 0);  // the redo ran inside the step graph
  EXPECT_EQ(waitingSteps, 0);
  EXPECT_LE(gpuWorst, 0.03);
  EXPECT_NEAR(gpuWorst, cpuWorst, 0.005);
  EXPECT_LE(std::abs(gpuMost - cpuMost), 3);
}
