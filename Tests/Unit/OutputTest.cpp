#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "Output/FrameWriter.h"
#include "Simulation/Runner.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {
std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(Output, FramesFollowFrameRateNotTimeStep) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation("<Scene><Simulation timeStep=\"0.015\" frameRate=\"20\" duration=\"0.5\"/>"
                                  "<WaterBlock max=\"0.06 0.06 0.06\"/></Scene>",
                                  Device::Cpu, reg);
  std::string dir = ::testing::TempDir() + "soak_output_test";
  std::system(("rm -rf " + dir).c_str());
  FrameWriter writer(dir, "<Scene/>");
  Runner runner(*sim, &writer);
  RunProgress p = runner.run(RunOptions{});
  EXPECT_EQ(p.frames, 10);
  EXPECT_EQ(writer.framesWritten(), 11);
  // Frame k is written at the first step at or after k / 20 s.
  std::string pvd = slurp(dir + "/water.pvd");
  EXPECT_NE(pvd.find("timestep=\"0.06\" group=\"\" part=\"0\" file=\"water/water_000001.vtu\""), std::string::npos)
      << pvd;
  EXPECT_NE(pvd.find("water/water_000010.vtu"), std::string::npos);
  // stats.csv: a header and one row per frame, with the documented columns.
  std::ifstream stats(dir + "/stats.csv");
  std::string header;
  std::getline(stats, header);
  for (const char* col : {"frame", "time", "water_particles", "cloth_particles", "step_ms", "free_water_mass"})
    EXPECT_NE(header.find(col), std::string::npos) << col;
  int rows = 0;
  for (std::string line; std::getline(stats, line);) ++rows;
  EXPECT_EQ(rows, 11);
}

TEST(Output, PvdIsValidAfterEveryFrame) {
  std::string dir = ::testing::TempDir() + "soak_pvd_test";
  std::system(("mkdir -p " + dir).c_str());
  PvdCollection pvd(dir + "/x.pvd");
  pvd.add(0.0, "a.vtu");
  std::string one = slurp(dir + "/x.pvd");
  EXPECT_NE(one.find("</VTKFile>"), std::string::npos);
  pvd.add(0.5, "b.vtu");
  std::string two = slurp(dir + "/x.pvd");
  EXPECT_NE(two.find("b.vtu"), std::string::npos);
  EXPECT_NE(two.find("</VTKFile>"), std::string::npos);
}
