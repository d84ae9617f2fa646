// The soak program as a user meets it: exit codes, messages, nothing written on bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "SoakProcess.h"
#include "Support/TempFiles.h"

namespace {
using Result = soak::test::SoakResult;
using soak::test::runSoak;
std::string tempDir(const std::string& name) { return soak::test::freshTempPath("cli_" + name); }
bool exists(const std::string& path) { return soak::test::pathExists(path); }
void writeFile(const std::string& path, const std::string& text) { soak::test::writeWholeFile(path, text); }
}  // namespace

TEST(Cli, TypoInSceneFailsWithLineAndNothingWritten) {
  std::string dir = tempDir("typo");
  std::string scene = soak::test::processTempPath("typo_scene.xml");
  writeFile(scene, "<Scene>\n  <Simulation duration=\"0.1\"/>\n  <Plane/>\n  <Sphere center=\"0 0 0\" radus=\"0.2\"/>\n</Scene>\n");
  Result r = runSoak("run " + scene + " -o " + dir + " --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("typo_scene.xml:4"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("did you mean 'radius'"), std::string::npos) << r.output;
  EXPECT_FALSE(exists(dir)) << "an output folder was created for a bad scene";
}

TEST(Cli, RunWritesFramesAndSummary) {
  std::string dir = tempDir("ok");
  Result r = runSoak("run " + std::string(SOAK_SOURCE_DIR) + "/Scenes/falling_particles.xml -o " + dir +
                     " --frames 3 --device cpu --set Simulation.frameRate=10 --profile");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(exists(dir + "/water.pvd"));
  EXPECT_TRUE(exists(dir + "/water/water_000003.vtu"));
  EXPECT_FALSE(exists(dir + "/water/water_000004.vtu"));
  EXPECT_TRUE(exists(dir + "/scene.xml"));
  EXPECT_NE(r.output.find("progress: frame 3/3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("neighbours"), std::string::npos) << "profile table missing: " << r.output;
  std::ifstream sceneAsRun(dir + "/scene.xml");
  std::string text((std::istreambuf_iterator<char>(sceneAsRun)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("frameRate=\"10\""), std::string::npos) << "override missing from scene.xml";
}

TEST(Cli, OptionAndDeviceErrors) {
  EXPECT_EQ(runSoak("run").code, 2);
  EXPECT_EQ(runSoak("run x.xml --frames -3").code, 2);
  EXPECT_EQ(runSoak("run x.xml --bogus").code, 2);
  Result missing = runSoak("run /nonexistent/scene.xml");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.output.find("cannot open scene file"), std::string::npos);
  Result dev = runSoak("run " + std::string(SOAK_SOURCE_DIR) + "/Scenes/falling_particles.xml --device tpu");
  EXPECT_EQ(dev.code, 2) << dev.output;
  EXPECT_EQ(runSoak("frobnicate").code, 2);
  EXPECT_EQ(runSoak("help").code, 0);
  Result v = runSoak("version");
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.output.find("backends: cpu"), std::string::npos);
}

TEST(Cli, CudaRequestWithoutGpuIsAClearError) {
  Result v = runSoak("version");
  if (v.output.find("GPU:") != std::string::npos) GTEST_SKIP() << "a GPU is present";
  std::string dir = tempDir("cuda");
  Result r = runSoak("run " + std::string(SOAK_SOURCE_DIR) + "/Scenes/falling_particles.xml --device cuda -o " + dir);
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("--device cuda"), std::string::npos) << r.output;
  EXPECT_FALSE(exists(dir));
}

TEST(Cli, UnwritableOutputFolderIsAnInputError) {
  Result r = runSoak("run " + std::string(SOAK_SOURCE_DIR) + "/Scenes/falling_particles.xml -o /proc/soak_out --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("output folder"), std::string::npos) << r.output;
}

TEST(Cli, RunawaySpeedStopsTheRunWithItsOwnCodeAndKeepsEarlierFrames) {
  // Falling particles pass 2 m/s after about 0.2 s: with maxSpeed = 2 that is
  // an instability. The run stops before writing the frame that shows it.
  const std::string scene = std::string(SOAK_SOURCE_DIR) + "/Scenes/falling_particles.xml";
  std::string dir = tempDir("unstable");
  Result r = runSoak("run " + scene + " -o " + dir + " --quiet --device cpu --set Simulation.maxSpeed=2");
  EXPECT_EQ(r.code, 4) << r.output;
  EXPECT_NE(r.output.find("above Simulation.maxSpeed = 2 m/s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("water particle"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--check-stages"), std::string::npos) << r.output;
  // 2 m/s is reached at t = 0.204 s: frames 0-5 (t <= 0.167 s at 30/s) are written, 6 is not.
  EXPECT_TRUE(exists(dir + "/water/water_000005.vtu"));
  EXPECT_FALSE(exists(dir + "/water/water_000006.vtu"));
  std::ifstream pvd(dir + "/water.pvd");
  std::string text((std::istreambuf_iterator<char>(pvd)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("water_000005.vtu"), std::string::npos);
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << "the collection is not closed";
  // With --check-stages the report names the stage: gravity enters in predict.
  Result staged = runSoak("run " + scene + " -o " + tempDir("unstable2") +
                          " --quiet --device cpu --check-stages --set Simulation.maxSpeed=2");
  EXPECT_EQ(staged.code, 4) << staged.output;
  EXPECT_NE(staged.output.find("after stage predict"), std::string::npos) << staged.output;
}
