// Counts stay on the device (issue 6): between maintenance steps a step
// never waits for the device, while water is emitted, drained, absorbed and
// dripped. Counted with hostWaits(), which the CPU backend counts through
// the same calls as the GPU's.
#include <gtest/gtest.h>

#include <cstdio>

#include "Backend/Device.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

// A saturated sheet that drips into a sink, a jet that wets it, water that
// falls past it into the sink, and a ball that moves along a path. Its
// cloth sub-steps are fixed (`travel` 0); with sub-steps from the cloth's
// speed (the chebyshev default, travel 0.5) the host reads the step's
// sub-step count back on the CPU and in a GPU step queued kernel by kernel,
// and with the strain redo (Cloth/StrainRedo.h) the sub-step and count
// again after the last sub-step (and after each redo's last: this scene's
// sheet is never redone); in a GPU step graph it does neither
// (Backend/DeviceLoop.h, Tests/Gpu/GpuAdaptiveSubstepsTest.cpp).
std::unique_ptr<Simulation> dripScene(test::TestRegistry& reg, const std::string& travel = "0",
                                      const std::string& redo = "1.5") {
  return test::makeSimulation(
      "<Scene><Simulation timeStep='0.005' domainMin='-2 -1 -2' domainMax='2 3 2' clothSubstepTravel='" + travel +
          "' clothStrainRedo='" + redo + "'/>"
      "<Cloth origin='-0.2 1 0' axisU='1 0 0' axisV='0 -1 0' width='0.4' height='0.4' cellsU='20' cellsV='20' "
      "pinCorners='u0v0 u1v0'/>"
      "<Nozzle position='0 0.8 0.3' direction='0 0 -1' radius='0.03' speed='3'/>"
      "<Sink min='-2 -1 -2' max='2 0.45 2'/>"
      "<Sphere center='0.8 0.8 0' radius='0.1' path='0 0 0 0; 2 0 0.5 0'/>"
      "<WetCloth initialSaturation='0.4'/></Scene>",
      Device::Cpu, reg);
}

}  // namespace

TEST(HostWaits, AStepWaitsForTheDeviceOnlyOnMaintenanceSteps) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = dripScene(reg);
  sim->sizeListsEveryStepOnCpu = false;  // as on the GPU
  int maintenanceWaits = 0, otherWaits = 0, maintenanceSteps = 0, otherSteps = 0;
  for (int s = 0; s < 200; ++s) {
    const bool maintenance = sim->maintenanceStep();
    const unsigned long long before = hostWaits();
    sim->step();
    const int waits = int(hostWaits() - before);
    (maintenance ? maintenanceWaits : otherWaits) += waits;
    (maintenance ? maintenanceSteps : otherSteps) += 1;
    if (!maintenance && waits > 0) ADD_FAILURE() << "step " << s << " waited " << waits << " times";
  }
  const StatsRow row = sim->collectStats();
  std::printf("200 steps: %d maintenance steps waited %d times, %d others %d; drips %.0f, drained %.4f kg, "
              "emitted %.4f kg\n",
              maintenanceSteps, maintenanceWaits, otherSteps, otherWaits, row.get("drips_spawned"),
              row.get("drained_water_mass"), row.get("emitted_water_mass"));
  // Every path that changes the particle count was taken.
  EXPECT_GT(row.get("drips_spawned"), 0.0);
  EXPECT_GT(row.get("drained_water_mass"), 0.0);
  EXPECT_GT(row.get("emitted_water_mass"), 0.0);
  EXPECT_EQ(maintenanceSteps, 200 / sim->maintenanceInterval + (200 % sim->maintenanceInterval ? 1 : 0));
  EXPECT_EQ(otherWaits, 0);
  EXPECT_GT(maintenanceWaits, 0);  // the counter counts: compaction reads the count back
}

TEST(HostWaits, SubstepsFromTheClothsSpeedCostOneWaitAStepAndTheStrainRedoOneMore) {
  for (const char* redo : {"0", "1.5"}) {
    test::TestRegistry reg(SOAK_PLUGIN_DIR);
    auto sim = dripScene(reg, "0.5", redo);
    sim->sizeListsEveryStepOnCpu = false;
    for (int s = 0; s < 60; ++s) {
      const bool maintenance = sim->maintenanceStep();
      const unsigned long long before = hostWaits();
      sim->step();
      if (!maintenance) EXPECT_EQ(int(hostWaits() - before), redo[0] == '0' ? 1 : 2) << "redo " << redo << ", step " << s;
    }
  }
}
