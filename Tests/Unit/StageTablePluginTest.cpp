// A stage added to the wetting pipeline by another plugin, the way
// Doc/plugins.md ("A stage of your own in the wetting pipeline") walks
// through it: the Wring test plugin (Tests/Plugins/Wring) is one stage file
// and one stage-table row, anchored on WetCloth's published stage name and
// reading its published channels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "Support/TestScenes.h"

using namespace soak;

namespace {

struct WetRun {
  float maxSaturation = 0.f;     // over the run, at the end of each step
  double firstTotal = 0.0, lastTotal = 0.0;  // total_water_mass
  double buffered = 0.0;         // at the end
  std::vector<std::string> stages;
};

// A block of water on a sheet pinned at its corners; with <Wring> ahead
// of <WetCloth> (the scene's order does not matter).
WetRun run(const std::string& wring) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  reg.loader.loadFile(std::string(SOAK_TEST_PLUGIN_DIR) + "/libsoak_Wring.so");
  auto sim = test::makeSimulation(
      "<Scene>" + wring +
          "<Cloth origin='-0.3 0.5 -0.3' axisU='1 0 0' axisV='0 0 1' width='0.6' height='0.6' cellsU='24' "
          "cellsV='24' pinCorners='u0v0 u1v0 u0v1 u1v1'/><WaterBlock min='-0.08 0.53 -0.08' max='0.08 0.7 0.08'/>"
          "<WetCloth/></Scene>",
      Device::Cpu, reg);
  WetRun r;
  r.stages = sim->pipeline.names();
  const int channel = sim->particles.findChannel("saturation");
  for (int s = 0; s < 80; ++s) {
    sim->step();
    const std::vector<float> S = sim->particles.downloadChannel(channel);
    r.maxSaturation = std::max(r.maxSaturation, *std::max_element(S.begin(), S.end()));
    const StatsRow row = sim->collectStats();
    if (s == 0) r.firstTotal = row.get("total_water_mass");
    r.lastTotal = row.get("total_water_mass");
    r.buffered = row.get("buffered_water_mass");
  }
  return r;
}

}  // namespace

TEST(StageTable, AStagePluggedIntoTheWettingPipelineRunsWhereItsRowSaysAndDoesItsPhysics) {
  const WetRun plain = run(""), wrung = run("<Wring cap='0.15'/>");
  // Its row: right after wet.diffuse.
  const auto& st = wrung.stages;
  const auto diffuse = std::find(st.begin(), st.end(), "wet.diffuse");
  ASSERT_NE(diffuse, st.end());
  ASSERT_NE(diffuse + 1, st.end());
  EXPECT_EQ(*(diffuse + 1), "wring.squeeze");
  EXPECT_EQ(std::find(plain.stages.begin(), plain.stages.end(), "wring.squeeze"), plain.stages.end());
  std::printf("largest saturation: without Wring %.3f, with cap 0.15 %.4f; buffered water %.4f -> %.4f kg; "
              "total water %.7f -> %.7f kg\n",
              plain.maxSaturation, wrung.maxSaturation, plain.buffered, wrung.buffered, wrung.firstTotal,
              wrung.lastTotal);
  EXPECT_GT(plain.maxSaturation, 0.2f);               // the cloth does get wetter than the cap
  EXPECT_LE(wrung.maxSaturation, 0.15f + 1e-6f);       // and the stage keeps it at the cap
  EXPECT_GT(wrung.buffered, plain.buffered);           // what it wrung out went to the buffers
  EXPECT_NEAR(wrung.lastTotal, wrung.firstTotal, 1e-5 * wrung.firstTotal);  // no water made or lost
}
