// Crash safety and checkpoints, through the soak program: a run killed with
// SIGKILL leaves collections that list only whole frames; a run resumed from
// its checkpoint writes frames bit-identical to an uninterrupted run; a
// corrupted or mismatched checkpoint is refused.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include "SoakProcess.h"

using namespace soak::test;

namespace {

// Water from a nozzle on a wet sheet hung by two corners: emission, drips
// queued between steps, absorption, cloth sub-steps: every kind of state.
const char* kScene = R"(<Scene>
  <Simulation timeStep="0.015" frameRate="30" clothIterations="4" clothSubsteps="2"/>
  <Water/>
  <Cloth name="sheet" origin="-0.3 1.0 0" axisU="1 0 0" axisV="0 -1 0" width="0.6" height="0.6" cellsU="15"
         cellsV="15" pinCorners="u0v0 u1v1"/>
  <Plane point="0 0 0" normal="0 1 0"/>
  <Nozzle position="0 1.2 0.15" direction="0 -1 -0.5" radius="0.03" speed="2"/>
  <WetCloth initialSaturation="0.4"/>
</Scene>
)";

// The same sheet under the chebyshev solve with sub-steps from its speed
// (Cloth/AdaptiveSubsteps.h): a step's sub-steps come from its state alone.
const char* kSceneSubstepsFromSpeed = R"(<Scene>
  <Simulation timeStep="0.015" frameRate="30" clothIterations="6" clothSubsteps="2" clothSubstepTravel="0.3"/>
  <Water/>
  <Cloth name="sheet" model="chebyshev" origin="-0.3 1.0 0" axisU="1 0 0" axisV="0 -1 0" width="0.6" height="0.6"
         cellsU="15" cellsV="15" pinCorners="u0v0 u1v1"/>
  <Plane point="0 0 0" normal="0 1 0"/>
  <Nozzle position="0 1.2 0.15" direction="0 -1 -0.5" radius="0.03" speed="2"/>
  <WetCloth initialSaturation="0.4"/>
</Scene>
)";

// The same sheet with nothing named: the default solver, whose sub-steps
// also follow the strain its solve leaves (state a checkpoint keeps).
const char* kSceneSolversOwnCounts = R"(<Scene>
  <Simulation timeStep="0.015" frameRate="30"/>
  <Water/>
  <Cloth name="sheet" origin="-0.3 1.0 0" axisU="1 0 0" axisV="0 -1 0" width="0.6" height="0.6"
         cellsU="15" cellsV="15" pinCorners="u0v0 u1v1"/>
  <Plane point="0 0 0" normal="0 1 0"/>
  <Nozzle position="0 1.2 0.15" direction="0 -1 -0.5" radius="0.03" speed="2"/>
  <WetCloth initialSaturation="0.4"/>
</Scene>
)";

// One file per test: ctest runs tests in parallel processes, and a file
// shared between them could be read by one while another rewrites it.
std::string sceneFile(const char* xml = kScene) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string path = ::testing::TempDir() + "soak_checkpoint_" + test + ".xml";
  writeWholeFile(path, xml);
  return path;
}

std::string frameFile(const std::string& dir, const std::string& kind, int frame) {
  char name[64];
  std::snprintf(name, sizeof(name), "%s_%06d.%s", kind.c_str(), frame, kind == "water" ? "vtu" : "vtp");
  return dir + "/" + kind + "/" + name;
}

// stats.csv without its last column (step_ms, a wall-clock time).
std::vector<std::string> statsWithoutTiming(const std::string& dir) {
  std::istringstream in(readWholeFile(dir + "/stats.csv"));
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(line.substr(0, line.find_last_of(',')));
  return rows;
}

// Files listed by a .pvd collection.
void expectSameFrames(const std::string& a, const std::string& b, int frames) {
  int compared = 0;
  for (int f = 0; f <= frames; ++f)
    for (const char* kind : {"water", "cloth_sheet"}) {
      const std::string fa = frameFile(a, kind, f), fb = frameFile(b, kind, f);
      ASSERT_TRUE(pathExists(fb)) << fb;
      EXPECT_TRUE(readWholeFile(fa) == readWholeFile(fb)) << fb << " differs from " << fa;
      ++compared;
    }
  EXPECT_FALSE(pathExists(frameFile(b, "water", frames + 1)));
  EXPECT_EQ(statsWithoutTiming(a), statsWithoutTiming(b));
  EXPECT_EQ(pvdFiles(a + "/water.pvd"), pvdFiles(b + "/water.pvd"));
  EXPECT_EQ(pvdFiles(a + "/cloth_sheet.pvd"), pvdFiles(b + "/cloth_sheet.pvd"));
  std::printf("checkpoint: %d frame files compared byte for byte\n", compared);
}

}  // namespace

TEST(Checkpoint, ResumeAfterAKillWritesFramesBitIdenticalToAnUninterruptedRun) {
  const std::string scene = sceneFile();
  const std::string whole = freshTempPath("ckpt_whole"), killed = freshTempPath("ckpt_killed");
  const int frames = 40;
  SoakResult a = runSoak("run " + scene + " -o " + whole + " --frames " + std::to_string(frames) +
                         " --device cpu --quiet");
  ASSERT_EQ(a.code, 0) << a.output;

  // Killed (SIGKILL) once frame 14 is on disk: the last checkpoint is frame
  // 12 or later, and frames past it may be on disk too.
  const pid_t pid = startSoak({"run", scene, "-o", killed, "--frames", std::to_string(frames), "--device", "cpu",
                               "--quiet", "--checkpoint-every", "4"});
  ASSERT_TRUE(waitForFile(pid, frameFile(killed, "water", 14))) << "the run ended before it could be killed";
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));

  // What the kill left: every frame a collection lists is on disk whole.
  const std::vector<std::string> listed = pvdFiles(killed + "/water.pvd");
  ASSERT_GE(listed.size(), 14u);  // frame 14 is on disk before the .pvd lists it
  for (const std::string& f : listed) {
    const std::string text = readWholeFile(killed + "/" + f);
    EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << f << " is listed but not whole";
  }

  SoakResult r = runSoak("run --resume " + killed + " --device cpu");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("resuming"), std::string::npos) << r.output;
  expectSameFrames(whole, killed, frames);
}

// Chaos: a checkpointing run killed with SIGKILL at random moments, twelve
// times, each time resumed (or, killed before its first checkpoint, started
// again), ends with frames bit-identical to an uninterrupted run's. The
// moments are drawn from a seed the test prints (SOAK_CHAOS_SEED repeats it).
TEST(Checkpoint, TwelveKillsAtRandomMomentsEndInFramesBitIdenticalToAnUninterruptedRun) {
  const std::string scene = sceneFile();
  const std::string whole = freshTempPath("chaos_whole"), killed = freshTempPath("chaos_killed");
  const int frames = 40, kKills = 12;
  auto timed = [](const std::string& args) {
    const auto start = std::chrono::steady_clock::now();
    const SoakResult r = runSoak(args);
    EXPECT_EQ(r.code, 0) << r.output;
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };
  // The start (load, set-up, frame 0) and the work after it.
  const double startMs = timed("run " + scene + " -o " + freshTempPath("chaos_start") + " --frames 0 --device cpu --quiet");
  const double wholeMs = timed("run " + scene + " -o " + whole + " --frames " + std::to_string(frames) +
                               " --device cpu --quiet");
  ASSERT_FALSE(HasFailure());
  const double workMs = std::max(wholeMs - startMs, 1.0);

  const char* seedText = std::getenv("SOAK_CHAOS_SEED");
  const unsigned seed = seedText ? unsigned(std::strtoul(seedText, nullptr, 10)) : std::random_device{}();
  std::printf("chaos: seed %u (SOAK_CHAOS_SEED=%u repeats these moments), start %.0f ms, whole run %.0f ms\n", seed,
              seed, startMs, wholeMs);
  std::mt19937 rng(seed);
  // Each life is killed at a random moment within its first three frames
  // past what the folder listed when it started (a moment drawn from the
  // frames it writes, not from the clock alone, so that a machine that is
  // slower or faster than when the whole run was timed draws alike): twelve
  // lives cover about two thirds of the run, and a kill falls anywhere
  // between two checkpoints (every 2 frames).
  const double frameMs = workMs / frames;
  std::uniform_int_distribution<int> framesInLife(0, 2);
  std::uniform_real_distribution<double> partOfFrame(0.0, 1.0);
  int kills = 0, restarts = 0, resumes = 0;
  for (int life = 0; life < 200; ++life) {
    const bool resume = pathExists(killed + "/checkpoint.soak");
    const std::size_t listedAtStart = pvdFiles(killed + "/water.pvd").size();
    const pid_t pid = resume ? startSoak({"run", "--resume", killed, "--device", "cpu", "--quiet"})
                             : startSoak({"run", scene, "-o", killed, "--frames", std::to_string(frames), "--device",
                                          "cpu", "--quiet", "--checkpoint-every", "2", "--overwrite"});
    (resume ? resumes : restarts) += life > 0;
    if (kills < kKills) {
      const std::size_t target = listedAtStart + 1 + std::size_t(framesInLife(rng));
      int status = 0;
      bool running = true;
      while ((running = waitpid(pid, &status, WNOHANG) == 0) && pvdFiles(killed + "/water.pvd").size() < target)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      if (running) {
        std::this_thread::sleep_for(std::chrono::microseconds(int(1000.0 * frameMs * partOfFrame(rng))));
        running = waitpid(pid, &status, WNOHANG) == 0;
      }
      if (running) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status));
        ++kills;
        for (const std::string& f : pvdFiles(killed + "/water.pvd"))
          ASSERT_NE(readWholeFile(killed + "/" + f).find("</VTKFile>"), std::string::npos)
              << f << " is listed but not whole after kill " << kills;
        continue;
      }
      ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "life " << life << " failed on its own";
    } else {
      ASSERT_EQ(exitCodeOf(pid), 0) << "the last life failed";
    }
    if (pvdFiles(killed + "/water.pvd").size() == std::size_t(frames + 1)) break;
  }
  std::printf("chaos: %d kills, %d resumes, %d fresh starts (killed before the first checkpoint)\n", kills, resumes,
              restarts);
  EXPECT_EQ(kills, kKills);
  EXPECT_GT(resumes, 0);
  expectSameFrames(whole, killed, frames);
}

TEST(Checkpoint, AFinishedRunCanBeExtendedAndKeepsItsCheckpointInterval) {
  const std::string scene = sceneFile();
  const std::string whole = freshTempPath("ckpt_whole2"), extended = freshTempPath("ckpt_extended");
  ASSERT_EQ(runSoak("run " + scene + " -o " + whole + " --frames 12 --device cpu --quiet").code, 0);
  ASSERT_EQ(runSoak("run " + scene + " -o " + extended + " --frames 5 --device cpu --quiet --checkpoint-every 10").code,
            0);
  SoakResult done = runSoak("run --resume " + extended + " --device cpu --quiet");
  EXPECT_EQ(done.code, 2) << "nothing left to do must be said, not silently ignored";
  EXPECT_NE(done.output.find("already reached frame 5"), std::string::npos) << done.output;
  SoakResult r = runSoak("run --resume " + extended + " --frames 12 --device cpu --quiet");
  ASSERT_EQ(r.code, 0) << r.output;
  expectSameFrames(whole, extended, 12);
}

// Runs `xml` `total` frames whole and `split` + the rest resumed, compares
// the frames and returns the most cloth sub-steps a frame's step took.
int mostSubstepsOfAResumedRun(const char* xml, const std::string& name, int split = 5, int total = 12) {
  const std::string scene = sceneFile(xml);
  const std::string whole = freshTempPath("ckpt_whole_" + name), extended = freshTempPath("ckpt_extended_" + name);
  EXPECT_EQ(runSoak("run " + scene + " -o " + whole + " --frames " + std::to_string(total) + " --device cpu --quiet").code,
            0);
  EXPECT_EQ(runSoak("run " + scene + " -o " + extended + " --frames " + std::to_string(split) +
                    " --device cpu --quiet --checkpoint-every 100").code,
            0);
  SoakResult r = runSoak("run --resume " + extended + " --frames " + std::to_string(total) + " --device cpu --quiet");
  EXPECT_EQ(r.code, 0) << r.output;
  expectSameFrames(whole, extended, total);
  const std::vector<std::string> rows = statsWithoutTiming(whole);
  std::istringstream header(rows.at(0));
  int column = 0, substepsColumn = -1;
  for (std::string name; std::getline(header, name, ',');) {
    if (name == "cloth_substeps") substepsColumn = column;
    ++column;
  }
  EXPECT_GE(substepsColumn, 0);
  if (substepsColumn < 0) return 0;
  int most = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    std::istringstream row(rows[k]);
    std::string cell;
    for (int c = 0; c <= substepsColumn; ++c) std::getline(row, cell, ',');
    most = std::max(most, std::stoi(cell));
  }
  return most;
}

TEST(Checkpoint, ARunWithSubstepsFromTheClothsSpeedResumesBitIdentical) {
  // The sheet swings: the run took more sub-steps than its fewest (2) somewhere.
  EXPECT_GT(mostSubstepsOfAResumedRun(kSceneSubstepsFromSpeed, "travel"), 2);
}

TEST(Checkpoint, ARunWithTheSolversOwnSubstepsResumesBitIdentical) {
  // Hung from a diagonal, the sheet's strain raises its sub-steps past the
  // fewest (4) between frames 9 and 10 (the speed alone would not): the
  // checkpoint at frame 12 holds the raised count, and a resume that lost it
  // would take 4 again.
  EXPECT_GT(mostSubstepsOfAResumedRun(kSceneSolversOwnCounts, "own", 12, 16), 4);
}

TEST(Checkpoint, CorruptedTruncatedOrMismatchedCheckpointsAreRefused) {
  const std::string scene = sceneFile();
  const std::string dir = freshTempPath("ckpt_bad");
  ASSERT_EQ(runSoak("run " + scene + " -o " + dir + " --frames 3 --device cpu --quiet --checkpoint-every 3").code, 0);
  const std::string ckpt = dir + "/checkpoint.soak", good = readWholeFile(ckpt);
  ASSERT_GT(good.size(), 1000u);
  const std::string statsBefore = readWholeFile(dir + "/stats.csv");

  auto refused = [&](const std::string& why, const std::string& expected) {
    SoakResult r = runSoak("run --resume " + dir + " --frames 6 --device cpu --quiet");
    EXPECT_EQ(r.code, 2) << why << ": " << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << why << ": " << r.output;
    EXPECT_FALSE(pathExists(frameFile(dir, "water", 4))) << why << ": a refused resume wrote a frame";
    EXPECT_EQ(readWholeFile(dir + "/stats.csv"), statsBefore) << why << ": a refused resume touched stats.csv";
  };
  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;
  writeWholeFile(ckpt, flipped);
  refused("one bit flipped", "checksum does not match");
  writeWholeFile(ckpt, good.substr(0, good.size() - 100));
  refused("truncated", "truncated");
  writeWholeFile(ckpt, "not a checkpoint at all");
  refused("foreign file", "not a Soak checkpoint");
  std::remove(ckpt.c_str());
  refused("missing", "no checkpoint here");

  writeWholeFile(ckpt, good);
  const std::string sceneAsRun = readWholeFile(dir + "/scene.xml");
  std::string edited = sceneAsRun;
  edited.replace(edited.find("cellsU=\"15\""), 11, "cellsU=\"16\"");
  writeWholeFile(dir + "/scene.xml", edited);
  refused("scene edited", "differs from the scene the checkpoint was written for");
  writeWholeFile(dir + "/scene.xml", sceneAsRun);

  SoakResult withScene = runSoak("run " + scene + " --resume " + dir);
  EXPECT_EQ(withScene.code, 2) << withScene.output;
  SoakResult ok = runSoak("run --resume " + dir + " --frames 6 --device cpu --quiet");
  EXPECT_EQ(ok.code, 0) << "the intact checkpoint must still resume: " << ok.output;
}

TEST(Checkpoint, SigintFinishesTheFrameWritesACheckpointAndStopsCleanly) {
  const std::string scene = sceneFile();
  const std::string dir = freshTempPath("ckpt_sigint"), whole = freshTempPath("ckpt_whole3");
  ASSERT_EQ(runSoak("run " + scene + " -o " + whole + " --frames 30 --device cpu --quiet").code, 0);
  const pid_t pid = startSoak({"run", scene, "-o", dir, "--frames", "30", "--device", "cpu",
                               "--quiet", "--checkpoint-every", "100"});
  ASSERT_TRUE(waitForFile(pid, frameFile(dir, "water", 6))) << "the run ended before it could be interrupted";
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "SIGINT must end the run through its own exit path";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  // Every listed frame is whole, and the checkpoint (written on the way out,
  // although the interval is 100) continues the run to the same end.
  const std::vector<std::string> listed = pvdFiles(dir + "/water.pvd");
  ASSERT_GE(listed.size(), 6u);
  ASSERT_LT(listed.size(), 31u);
  SoakResult r = runSoak("run --resume " + dir + " --device cpu --quiet");
  ASSERT_EQ(r.code, 0) << r.output;
  expectSameFrames(whole, dir, 30);
}
