// `soak sweep` through the soak program: the local executor runs every
// point, a second run does only what is missing or failed, Ctrl-C stops the
// runs cleanly and they resume, print gives one line per point, collect
// gathers the figures.
#include <gtest/gtest.h>
#include <signal.h>

#include <sstream>

#include "Sweep/SweepFolder.h"
#include "SoakProcess.h"

using namespace soak;
using namespace soak::test;

namespace {

const std::string kScene = std::string(SOAK_SOURCE_DIR) + "/Tests/Sweep/wet_sheet.xml";

std::string plan(const std::string& name, const std::string& vary, int frames) {
  const std::string dir = freshTempPath(name);
  const SoakResult r = runSoak("sweep plan -o " + dir + " --scene " + kScene + " --device cpu --frames " +
                               std::to_string(frames) + " --checkpoint-every 2 --vary '" + vary + "'");
  EXPECT_EQ(r.code, 0) << r.output;
  return dir;
}

std::vector<std::string> statuses(const std::string& dir) {
  std::vector<std::string> s;
  for (const PointRecord& r : loadSweep(dir).records) s.push_back(r.status);
  return s;
}

std::vector<int> attempts(const std::string& dir) {
  std::vector<int> a;
  for (const PointRecord& r : loadSweep(dir).records) a.push_back(r.attempts);
  return a;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(SweepRun, LocalRunsEveryPointAndASecondRunOnlyWhatIsMissingOrFailed) {
  const std::string dir = plan("sweep_local", "Nozzle.speed=list 1 2 80", 3);
  SoakResult r = runSoak("sweep run " + dir + " --jobs 2 --threads 1");
  EXPECT_EQ(r.code, 6) << "a failed point is an exit code of its own\n" << r.output;
  EXPECT_EQ(statuses(dir), (std::vector<std::string>{"done", "done", "failed"}));
  const SweepState s = loadSweep(dir);
  EXPECT_EQ(s.records[2].exitCode, 4);
  EXPECT_NE(s.records[2].error.find("maxSpeed"), std::string::npos) << s.records[2].error;
  EXPECT_GT(s.records[0].wallSeconds, 0.0);
  for (const SweepPoint& p : s.points)
    EXPECT_EQ(pvdFiles(s.layout.runDir(p.id) + "/water.pvd").size(), p.values[0] == "80" ? 1u : 4u) << p.id;
  const std::string manifest = readWholeFile(dir + "/manifest.csv");
  EXPECT_EQ(count(manifest, ",done,0,"), 2) << manifest;
  EXPECT_EQ(count(manifest, ",failed,4,"), 1) << manifest;

  // Again: only the failed point runs (and fails again); the done ones are
  // left as they are.
  r = runSoak("sweep run " + dir + " --jobs 2 --threads 1");
  EXPECT_EQ(r.code, 6) << r.output;
  EXPECT_NE(r.output.find("1 of 3 points to run"), std::string::npos) << r.output;
  EXPECT_EQ(attempts(dir), (std::vector<int>{1, 1, 2}));

  // A point whose folder is lost is missing: planned again and run alone.
  std::system(("rm -rf '" + s.layout.pointDir(s.points[1].id) + "'").c_str());
  ASSERT_EQ(runSoak("sweep plan -o " + dir + " --scene " + kScene +
                    " --device cpu --frames 3 --checkpoint-every 2 --vary 'Nozzle.speed=list 1 2 80'")
                .code,
            0);
  EXPECT_EQ(statuses(dir), (std::vector<std::string>{"done", "planned", "failed"}));
  r = runSoak("sweep run " + dir + " --jobs 2 --threads 1");
  EXPECT_NE(r.output.find("2 of 3 points to run"), std::string::npos) << r.output;
  EXPECT_EQ(statuses(dir), (std::vector<std::string>{"done", "done", "failed"}));
  EXPECT_EQ(attempts(dir), (std::vector<int>{1, 1, 3}));
}

TEST(SweepRun, CtrlCStopsTheRunsCleanlyAndTheNextRunResumesThem) {
  const std::string dir = plan("sweep_interrupt", "Nozzle.speed=list 1 2", 40);
  const SweepState s = loadSweep(dir);
  const pid_t pid = startSoak({"sweep", "run", dir, "--jobs", "2", "--threads", "1"});
  // Once both runs have a checkpoint, Ctrl-C (SIGINT to the sweep alone, as a
  // terminal sends it: the runs are in process groups of their own).
  for (const SweepPoint& p : s.points)
    ASSERT_TRUE(waitForFile(pid, s.layout.runDir(p.id) + "/checkpoint.soak")) << "the sweep ended first";
  kill(pid, SIGINT);
  EXPECT_EQ(exitCodeOf(pid), 130);
  EXPECT_EQ(statuses(dir), (std::vector<std::string>{"interrupted", "interrupted"}));
  const std::string manifest = readWholeFile(dir + "/manifest.csv");
  EXPECT_EQ(count(manifest, ",interrupted,130,"), 2) << manifest;
  for (const SweepPoint& p : s.points) {
    const std::size_t frames = pvdFiles(s.layout.runDir(p.id) + "/water.pvd").size();
    EXPECT_GT(frames, 1u);
    EXPECT_LT(frames, 41u);
  }

  const SoakResult r = runSoak("sweep run " + dir + " --jobs 2 --threads 1");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(statuses(dir), (std::vector<std::string>{"done", "done"}));
  EXPECT_EQ(attempts(dir), (std::vector<int>{2, 2}));
  for (const SweepPoint& p : s.points) {
    EXPECT_EQ(pvdFiles(s.layout.runDir(p.id) + "/water.pvd").size(), 41u);
    EXPECT_NE(readWholeFile(s.layout.log(p.id)).find("run --resume " + s.layout.runDir(p.id)), std::string::npos)
        << readWholeFile(s.layout.log(p.id));
  }
}

TEST(SweepRun, PrintGivesOneLinePerPointNotDone) {
  const std::string dir = plan("sweep_print", "WetCloth.initialSaturation=linear 0.1 0.3 3", 2);
  SoakResult r = runSoak("sweep run " + dir + " --executor print 2>/dev/null");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(count(r.output, "\n"), 3) << r.output;
  EXPECT_EQ(count(r.output, " sweep task " + dir + " p"), 3) << r.output;
  r = runSoak("sweep run " + dir + " --executor print --plain 2>/dev/null");
  EXPECT_EQ(count(r.output, " run " + dir + "/points/p"), 3) << r.output;
  EXPECT_EQ(count(r.output, " --frames 2 --checkpoint-every 2 --device cpu --quiet\n"), 3) << r.output;

  // One line run by hand is a point done; it is left out from then on.
  const std::string first = r.output.substr(0, r.output.find('\n'));
  r = runSoak("sweep run " + dir + " --executor print 2>/dev/null");
  const std::string task = r.output.substr(0, r.output.find('\n'));
  ASSERT_EQ(runShell(task).code, 0) << task;
  r = runSoak("sweep run " + dir + " --executor print 2>/dev/null");
  EXPECT_EQ(count(r.output, "\n"), 2) << r.output;
  EXPECT_EQ(r.output.find(task.substr(task.rfind(' '))), std::string::npos) << r.output;
}

TEST(SweepRun, CollectWritesFiguresOfDonePointsAndAPlot) {
  const std::string dir = plan("sweep_collect", "WetCloth.initialSaturation=list 0.1 0.3", 3);
  ASSERT_EQ(runSoak("sweep run " + dir + " --jobs 2 --threads 1").code, 0);
  SoakResult r = runSoak("sweep collect " + dir + " --figures held,steps,max:max_speed --plot held --against "
                         "WetCloth.initialSaturation");
  ASSERT_EQ(r.code, 0) << r.output;
  std::istringstream csv(readWholeFile(dir + "/collect.csv"));
  std::string header, a, b, extra;
  std::getline(csv, header);
  std::getline(csv, a);
  std::getline(csv, b);
  EXPECT_FALSE(std::getline(csv, extra));
  EXPECT_EQ(header, "point,repeat,WetCloth.initialSaturation,status,held,steps,max:max_speed");
  // Cloth that starts wetter holds more water; both ran 3 frames of 2 steps.
  auto held = [](const std::string& row) {
    std::vector<std::string> f;
    std::istringstream in(row);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    return f;
  };
  ASSERT_EQ(held(a).size(), 7u) << a;
  EXPECT_EQ(held(a)[3], "done");
  EXPECT_GT(std::stod(held(b)[4]), 2.0 * std::stod(held(a)[4])) << a << "\n" << b;
  EXPECT_EQ(held(a)[5], held(b)[5]);
  const std::string svg = readWholeFile(dir + "/plot-held.svg");
  EXPECT_EQ(count(svg, "<circle"), 2) << svg;
  EXPECT_NE(svg.find("WetCloth.initialSaturation"), std::string::npos);

  r = runSoak("sweep collect " + dir + " --figures hold");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("unknown figure 'hold'; did you mean 'held'"), std::string::npos) << r.output;
}
