// Scenes/garment.xml: a skirt (an OBJ with UVs) hung by its waist from a
// ball as from hips and soaked on one side by a jet, with the default cloth solver. It
// holds its shape: edge strain of a few percent at most, per frame, over
// the whole run (Doc/performance.md, "Default cloth solver").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "Support/TestScenes.h"

using namespace soak;

TEST(Garment, SkirtHungFromHipsAndSoakedByAJetHoldsItsShape) {
  // CI-sized: the first 2 s, the jet stopping at 1.2 s.
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  const std::string dir = std::string(SOAK_SOURCE_DIR) + "/Scenes/";
  std::ifstream in(dir + "garment.xml");
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(xml.empty());
  // The scene's mesh path is relative to the scene's folder.
  const std::string relative = "mesh=\"meshes/skirt.obj\"";
  const std::size_t at = xml.find(relative);
  ASSERT_NE(at, std::string::npos);
  xml.replace(at, relative.size(), "mesh=\"" + dir + "meshes/skirt.obj\"");
  auto sim = test::makeSimulation(xml, Device::Cpu, reg, {"Nozzle.stop=1.2"});
  double worstMean = 0.0, worstP99 = 0.0, heldWater = 0.0;
  const int steps = int(std::lround(2.0 / sim->settings.timeStep));
  for (int s = 1; s <= steps; ++s) {
    sim->step();
    if (s % 2 != 0) continue;
    const StatsRow row = sim->collectStats();
    worstMean = std::max(worstMean, row.get("strain_mean_skirt"));
    worstP99 = std::max(worstP99, row.get("strain_p99_skirt"));
    heldWater = std::max(heldWater, row.get("held_water_mass"));
  }
  std::printf("skirt hung from a ball under a jet, 2 s, default solver: worst frame strain mean %.2f %% p99 %.2f %%; "
              "most water held %.3f kg\n",
              100 * worstMean, 100 * worstP99, heldWater);
  EXPECT_LE(worstP99, 0.03);
  EXPECT_LE(worstMean, 0.01);
  EXPECT_GT(heldWater, 0.2);  // the jet soaks it: heavier by several percent of its 5.4 kg
}
