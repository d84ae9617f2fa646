#include <gtest/gtest.h>

#include <cmath>

#include "Base/Error.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(Plugin, LoadsFromDirectoryAndRegistersElements) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  EXPECT_TRUE(reg.registry.hasPlugin("AirDrag"));
  const ElementDecl* e = reg.registry.find("AirDrag");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->provider, "AirDrag");
  // Loading the same file again changes nothing.
  reg.loader.loadFile(std::string(SOAK_PLUGIN_DIR) + "/libsoak_AirDrag.so");
  EXPECT_EQ(reg.registry.plugins().size(), 2u);  // AirDrag and WetCloth
}

TEST(Plugin, CoreRunsWithoutPlugins) {
  test::TestRegistry reg;
  EXPECT_EQ(reg.registry.find("AirDrag"), nullptr);
  auto sim = test::makeSimulation("<Scene><WaterBlock max=\"0.04 0.04 0.04\"/></Scene>", Device::Cpu, reg);
  sim->step();
  EXPECT_EQ(sim->particles.count(), 8);
}

TEST(Plugin, SceneElementLoadsPluginByName) {
  test::TestRegistry reg;
  reg.loader.addSearchDirectory(SOAK_PLUGIN_DIR);
  auto sim = test::makeSimulation(
      "<Scene><Plugin name=\"AirDrag\"/><AirDrag coefficient=\"2\"/><WaterBlock max=\"0.02 0.02 0.02\"/></Scene>",
      Device::Cpu, reg);
  EXPECT_TRUE(sim->pipeline.has("airdrag.apply"));
}

TEST(Plugin, DragStageGivesTerminalVelocity) {
  // v_{n+1} = v_n e^{-k dt} + g dt  ->  v* = g dt / (1 - e^{-k dt})  (about g / k).
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  const double k = 2.0, dt = 0.01, g = 9.81;
  auto sim = test::makeSimulation("<Scene><Simulation timeStep=\"0.01\"/><AirDrag coefficient=\"2\"/>"
                                  "<WaterBlock max=\"0.02 0.02 0.02\"/></Scene>",
                                  Device::Cpu, reg);
  for (int s = 0; s < 1000; ++s) sim->step();
  const double vStar = g * dt / (1.0 - std::exp(-k * dt));
  EXPECT_NEAR(-sim->particles.downloadVelocities()[0].y, vStar, 1e-3 * vStar);
  EXPECT_NEAR(vStar, g / k, 0.02 * g / k);
}

TEST(Plugin, BadPluginsAreClearErrors) {
  test::TestRegistry reg;
  EXPECT_THROW(reg.loader.loadFile("/nonexistent/libsoak_X.so"), InputError);
  // A shared library that is not a plugin: the core library itself.
  try {
    reg.loader.loadFile(std::string(SOAK_PLUGIN_DIR) + "/../libsoak_core.so", "scene.xml:3");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a Soak plugin"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scene.xml:3"), std::string::npos);
  }
  reg.loader.addSearchDirectory(SOAK_PLUGIN_DIR);
  EXPECT_THROW(reg.loader.loadByName("NoSuchPlugin"), InputError);
}
