// A run folder belongs to one run (Output/RunFolder.h), through the soak
// program as a user meets it: a new run never replaces an earlier one unless
// asked, --overwrite leaves nothing of the earlier run, and two runs never
// write one folder at once.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "Base/Error.h"
#include "Output/RunFolder.h"
#include "SoakProcess.h"
#include "Support/TempFiles.h"

using namespace soak::test;

namespace {

// A small wet scene with a cloth named "sheet": frames, cloth collections,
// stats and checkpoints, a frame in well under a second on one core.
const char* kClothScene = R"(<Scene>
  <Simulation timeStep="0.015" frameRate="30" clothIterations="4" clothSubsteps="1"/>
  <Water/>
  <Cloth name="sheet" origin="-0.2 1.0 0" axisU="1 0 0" axisV="0 -1 0" width="0.4" height="0.4" cellsU="8"
         cellsV="8" pinCorners="u0v0 u1v0"/>
  <Plane point="0 0 0" normal="0 1 0"/>
  <Nozzle position="0 1.2 0.15" direction="0 -1 -0.5" radius="0.03" speed="2"/>
  <WetCloth/>
</Scene>
)";

std::string clothScene() {
  const std::string path = processTempPath("runfolder_cloth.xml");
  writeWholeFile(path, kClothScene);
  return path;
}

std::string fallingScene() { return std::string(SOAK_SOURCE_DIR) + "/Scenes/falling_particles.xml"; }

// Every file and folder under `dir`, relative to it, but the lock file.
std::set<std::string> listing(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string rel = std::filesystem::relative(e.path(), dir).string();
    if (rel != soak::kRunLockFile) names.insert(rel);
  }
  return names;
}

int framesListed(const std::string& dir) { return int(pvdFiles(dir + "/water.pvd").size()); }

}  // namespace

TEST(RunFolder, EntriesAreSortedIntoARunsOwnAndOthers) {
  for (const char* own : {"scene.xml", "stats.csv", "checkpoint.soak", "water.pvd", "water", "water_vdb",
                          "water_surface.pvd", "cloth_sheet.pvd", "cloth_sheet", "cloth_sheet_ply",
                          "water.pvd.tmp", "checkpoint.soak.tmp"})
    EXPECT_TRUE(soak::isRunEntry(own)) << own;
  for (const char* other : {"notes.txt", "render", "scene.xml.bak", "cloth_", "waterfall.png", soak::kRunLockFile})
    EXPECT_FALSE(soak::isRunEntry(other)) << other;
}

TEST(RunFolder, ANewRunIntoAFolderHoldingARunIsRefusedAndChangesNothing) {
  const std::string dir = freshTempPath("runfolder_refused");
  ASSERT_EQ(runSoak("run " + clothScene() + " -o " + dir + " --frames 3 --device cpu --quiet --checkpoint-every 3").code, 0);
  const std::set<std::string> before = listing(dir);
  const std::string pvd = readWholeFile(dir + "/water.pvd"), stats = readWholeFile(dir + "/stats.csv"),
                    ckpt = readWholeFile(dir + "/checkpoint.soak");

  const SoakResult r = runSoak("run " + fallingScene() + " -o " + dir + " --frames 1 --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("already holds a Soak run (4 frames listed in water.pvd, a checkpoint)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--resume " + dir), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
  EXPECT_EQ(listing(dir), before);
  EXPECT_EQ(readWholeFile(dir + "/water.pvd"), pvd);
  EXPECT_EQ(readWholeFile(dir + "/stats.csv"), stats);
  EXPECT_EQ(readWholeFile(dir + "/checkpoint.soak"), ckpt);

  // The default folder (soak-out/<scene>) follows the same rule.
  const std::string cwd = freshTempPath("runfolder_default");
  std::filesystem::create_directories(cwd);
  const std::string inCwd = "cd " + cwd + " && " + SOAK_BINARY + " run " + clothScene() + " --frames 1 --device cpu --quiet";
  ASSERT_EQ(runShell(inCwd).code, 0);
  EXPECT_EQ(runShell(inCwd).code, 2);
}

TEST(RunFolder, OverwriteLeavesNothingOfTheEarlierRunAndKeepsOtherFiles) {
  // The earlier run: a cloth, 6 frames, a checkpoint.
  const std::string dir = freshTempPath("runfolder_overwrite");
  ASSERT_EQ(runSoak("run " + clothScene() + " -o " + dir + " --frames 6 --device cpu --quiet --checkpoint-every 2").code, 0);
  ASSERT_TRUE(pathExists(dir + "/cloth_sheet/cloth_sheet_000006.vtp"));
  writeWholeFile(dir + "/notes.txt", "the user's own file");
  writeWholeFile(dir + "/water.pvd.tmp", "left by an interrupted write");

  // The new run (no cloth, 2 frames) must leave exactly what it leaves in
  // an empty folder, beside the user's file.
  const std::string clean = freshTempPath("runfolder_clean");
  ASSERT_EQ(runSoak("run " + fallingScene() + " -o " + clean + " --frames 2 --device cpu --quiet").code, 0);
  const SoakResult r = runSoak("run " + fallingScene() + " -o " + dir + " --frames 2 --device cpu --quiet --overwrite");
  ASSERT_EQ(r.code, 0) << r.output;
  std::set<std::string> expected = listing(clean);
  expected.insert("notes.txt");
  EXPECT_EQ(listing(dir), expected);
  EXPECT_FALSE(pathExists(dir + "/checkpoint.soak"));
  EXPECT_EQ(framesListed(dir), 3);
  EXPECT_EQ(readWholeFile(dir + "/notes.txt"), "the user's own file");
  EXPECT_EQ(readWholeFile(dir + "/scene.xml"), readWholeFile(clean + "/scene.xml"));

  // --overwrite and --resume together make no sense.
  EXPECT_EQ(runSoak("run --resume " + dir + " --overwrite").code, 2);
}

TEST(RunFolder, AFolderThatIsNotARunIsRefusedBeforeAnythingIsWritten) {
  const std::string dir = freshTempPath("runfolder_other");
  std::filesystem::create_directories(dir);
  writeWholeFile(dir + "/holiday.jpg", "x");
  SoakResult r = runSoak("run " + fallingScene() + " -o " + dir + " --frames 1 --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("is not empty: it holds 1 other entry (holiday.jpg)"), std::string::npos) << r.output;
  EXPECT_EQ(listing(dir), std::set<std::string>{"holiday.jpg"});

  // An output path that is a file, and a run folder whose 'water' is a file.
  const std::string file = freshTempPath("runfolder_file");
  writeWholeFile(file, "x");
  r = runSoak("run " + fallingScene() + " -o " + file + " --frames 1 --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("is a file, not a folder"), std::string::npos) << r.output;
  const std::string withWaterFile = freshTempPath("runfolder_waterfile");
  std::filesystem::create_directories(withWaterFile);
  writeWholeFile(withWaterFile + "/water", "x");
  r = runSoak("run " + fallingScene() + " -o " + withWaterFile + " --frames 1 --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(r.output.find("vtk"), std::string::npos) << r.output;
  EXPECT_EQ(runSoak("run " + fallingScene() + " -o " + withWaterFile + " --frames 1 --device cpu --quiet --overwrite").code, 0);
  EXPECT_EQ(framesListed(withWaterFile), 2);
}

TEST(RunFolder, ARunHoldsItsFolderUntilItEndsAndAKillLeavesNoStaleLock) {
  const std::string dir = freshTempPath("runfolder_lock");
  // A run far longer than the test, with a checkpoint every frame: met
  // while running on any machine, and killed below.
  const pid_t first = startSoak({"run", clothScene(), "-o", dir, "--frames", "100000", "--device", "cpu", "--quiet",
                                 "--checkpoint-every", "1"});
  ASSERT_TRUE(waitForFile(first, dir + "/checkpoint.soak")) << "the first run ended before it was met";

  const std::string pid = "process " + std::to_string(first) + " (";
  for (const std::string& second : {"run " + fallingScene() + " -o " + dir + " --frames 1 --device cpu --quiet --overwrite",
                                    "run " + clothScene() + " -o " + dir + " --frames 1 --device cpu --quiet",
                                    "run --resume " + dir + " --device cpu --quiet"}) {
    const SoakResult r = runSoak(second);
    EXPECT_EQ(r.code, 2) << second << "\n" << r.output;
    EXPECT_NE(r.output.find("is in use by another run: " + pid), std::string::npos) << second << "\n" << r.output;
  }
  EXPECT_NE(soak::runFolderHolder(dir).find(pid), std::string::npos);

  kill(first, SIGKILL);
  EXPECT_EQ(exitCodeOf(first), -1);
  EXPECT_EQ(soak::runFolderHolder(dir), "") << "a killed run left its lock";
  // The killed run's folder resumes: to two frames past what it listed.
  const int listed = framesListed(dir);
  const SoakResult resumed =
      runSoak("run --resume " + dir + " --frames " + std::to_string(listed + 1) + " --device cpu --quiet");
  EXPECT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_EQ(framesListed(dir), listed + 2);
}

TEST(RunFolder, TwoRunsStartedTogetherNeverShareAFolder) {
  for (int round = 0; round < 4; ++round) {
    const std::string dir = freshTempPath("runfolder_race" + std::to_string(round));
    // Told apart by their frame rates (in scene.xml) and frame counts.
    const pid_t a = startSoak({"run", clothScene(), "-o", dir, "--frames", "3", "--device", "cpu", "--quiet",
                               "--set", "Simulation.frameRate=30"});
    const pid_t b = startSoak({"run", clothScene(), "-o", dir, "--frames", "5", "--device", "cpu", "--quiet",
                               "--set", "Simulation.frameRate=20"});
    const int codeA = exitCodeOf(a), codeB = exitCodeOf(b);
    ASSERT_EQ(std::min(codeA, codeB), 0) << "round " << round << ": " << codeA << ", " << codeB;
    ASSERT_EQ(std::max(codeA, codeB), 2) << "round " << round << ": " << codeA << ", " << codeB;
    const bool aWon = codeA == 0;
    EXPECT_NE(readWholeFile(dir + "/scene.xml").find(aWon ? "frameRate=\"30\"" : "frameRate=\"20\""),
              std::string::npos) << "round " << round;
    const int frames = aWon ? 3 : 5;
    EXPECT_EQ(framesListed(dir), frames + 1) << "round " << round;
    EXPECT_TRUE(pathExists(dir + "/water/water_" + std::string(aWon ? "000003" : "000005") + ".vtu"));
    EXPECT_EQ(pathExists(dir + "/water/water_000004.vtu"), !aWon) << "the loser's frames are in the folder";
    const std::string stats = readWholeFile(dir + "/stats.csv");
    EXPECT_EQ(std::count(stats.begin(), stats.end(), '\n'), frames + 2) << stats;  // a header and the frames
  }
}

TEST(RunFolder, TheLockKeepsOutASecondRunInTheSameProcess) {
  const std::string dir = freshTempPath("runfolder_inprocess");
  std::filesystem::create_directories(dir);
  {
    const soak::RunFolderLock held = soak::RunFolderLock::acquire(dir);
    EXPECT_TRUE(held.held());
    EXPECT_THROW(soak::RunFolderLock::acquire(dir), soak::InputError);
    EXPECT_THROW(soak::claimRunFolder(dir, soak::FolderClaim::Overwrite), soak::InputError);
    EXPECT_NE(soak::runFolderHolder(dir).find("process " + std::to_string(getpid())), std::string::npos);
  }
  EXPECT_EQ(soak::runFolderHolder(dir), "");
  EXPECT_TRUE(soak::RunFolderLock::acquire(dir).held());
}
