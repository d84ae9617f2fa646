// What a run may take follows the process's own limits, not the machine's
// (Backend/ProcessLimits.h; Doc/reliability.md, "Resource limits"): a scene
// the machine's memory admits is refused under `ulimit -v` with the limit
// named, SOAK_MEMORY_LIMIT caps a run mid-way with exit 3 and its frames
// kept whole, and the CPU threads follow SLURM_CPUS_PER_TASK.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "Backend/Device.h"
#include "Backend/ProcessLimits.h"
#include "Base/Error.h"
#include "SoakProcess.h"

using namespace soak;
using namespace soak::test;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// A scene of about (side / 0.02)^3 water particles (the default spacing)
// and nothing else, a step of 1 ms and 1 frame.
std::string waterCubeScene(const std::string& name, double side) {
  const std::string path = freshTempPath(name) + ".xml";
  char block[160];
  std::snprintf(block, sizeof(block), "<WaterBlock min=\"0 0 0\" max=\"%g %g %g\"/>", side, side, side);
  writeWholeFile(path, std::string("<Scene><Simulation timeStep=\"0.001\" duration=\"0.002\" frameRate=\"1000\"/>"
                                   "<Water/>") + block + "</Scene>");
  return path;
}

class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    ::setenv(name, value, 1);
  }
  ~ScopedEnv() { had_ ? ::setenv(name_, old_.c_str(), 1) : ::unsetenv(name_); }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

}  // namespace

TEST(ProcessLimits, ByteSizesParseWithBinaryUnits) {
  EXPECT_EQ(parseByteSize("1048576"), 1048576.0);
  EXPECT_EQ(parseByteSize("8G"), 8.0 * 1024 * 1024 * 1024);
  EXPECT_EQ(parseByteSize("512M"), 512.0 * 1024 * 1024);
  EXPECT_EQ(parseByteSize("1.5GiB"), 1.5 * 1024 * 1024 * 1024);
  EXPECT_EQ(parseByteSize("4k"), 4096.0);
  EXPECT_LT(parseByteSize("lots"), 0.0);
  EXPECT_LT(parseByteSize("-1G"), 0.0);
  EXPECT_LT(parseByteSize("3X"), 0.0);
  EXPECT_LT(parseByteSize(""), 0.0);
}

TEST(ProcessLimits, CgroupFilesParse) {
  EXPECT_EQ(cgroupV2Path("0::/slurm/uid_0/job_7/step_0\n"), "/slurm/uid_0/job_7/step_0");
  EXPECT_EQ(cgroupV2Path("12:memory:/a\n0::/\n"), "/");
  EXPECT_EQ(cgroupV2Path("4:memory:/docker/abc\n"), "");
  EXPECT_EQ(parseCgroupLimit("8589934592\n"), 8589934592.0);
  EXPECT_LT(parseCgroupLimit("max\n"), 0.0);
  EXPECT_LT(parseCgroupLimit("9223372036854771712\n"), 0.0);  // v1's "no limit"
  EXPECT_LT(parseCgroupLimit(""), 0.0);
}

TEST(ProcessLimits, TheSmallestSetBoundWins) {
  EXPECT_LT(smallestBound({}).bytes, 0.0);
  const MemoryBound b = smallestBound({{32e9, "machine"}, {-1.0, "unset"}, {8e9, "ulimit"}, {16e9, "cgroup"}});
  EXPECT_EQ(b.bytes, 8e9);
  EXPECT_EQ(b.source, "ulimit");
}

TEST(ProcessLimits, SoakMemoryLimitBoundsTheBudgetAndEveryAllocation) {
  ScopedEnv env("SOAK_MEMORY_LIMIT", "64M");
  const MemoryBound b = deviceMemoryBudget(Device::Cpu);
  EXPECT_EQ(b.bytes, 64.0 * 1024 * 1024);
  EXPECT_EQ(b.source, "SOAK_MEMORY_LIMIT");
  void* small = deviceAllocate(Device::Cpu, 1 << 20);
  EXPECT_NE(small, nullptr);
  try {
    deviceAllocate(Device::Cpu, std::size_t(128) << 20);
    ADD_FAILURE() << "an allocation past SOAK_MEMORY_LIMIT was granted";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("SOAK_MEMORY_LIMIT"), std::string::npos) << e.what();
  }
  deviceFree(Device::Cpu, small);
  ScopedEnv bad("SOAK_MEMORY_LIMIT", "plenty");
  EXPECT_THROW(memoryLimitFromEnvironment(), InputError);
}

TEST(ProcessLimits, ASceneTheMachineHoldsIsRefusedUnderUlimitWithTheLimitNamed) {
  if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer's shadow memory needs terabytes of address space";
  // 4.1M particles (about 2 GiB at 512 bytes each): the machine's memory
  // holds them, a 2 GiB address space does not.
  const std::string big = waterCubeScene("ulimit_big", 3.2);
  const std::string out = freshTempPath("ulimit_big_out");
  SoakResult r = runShell("ulimit -v " + std::to_string(2 * 1024 * 1024) + "; exec " + std::string(SOAK_BINARY) +
                          " run " + big + " -o " + out + " --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("ulimit -v (RLIMIT_AS)"), std::string::npos) << r.output;
  EXPECT_FALSE(pathExists(out)) << "a refused run wrote its folder";
  // A scene that fits runs under the same limit.
  const std::string small = waterCubeScene("ulimit_small", 0.4);
  r = runShell("ulimit -v " + std::to_string(2 * 1024 * 1024) + "; exec " + std::string(SOAK_BINARY) + " run " +
               small + " -o " + freshTempPath("ulimit_small_out") + " --device cpu --quiet");
  EXPECT_EQ(r.code, 0) << r.output;
}

TEST(ProcessLimits, RunningOutOfDeviceMemoryMidRunEndsWithExitThreeAndKeepsTheFrames) {
  // Water poured from a nozzle for 1 s (12k particles at the end, about
  // 4 MiB of arrays): Simulation.maxParticles stands in for the budget, so
  // the run starts, and SOAK_MEMORY_LIMIT refuses the growth part way.
  const std::string scene = freshTempPath("oom_scene") + ".xml";
  writeWholeFile(scene,
                 "<Scene><Simulation timeStep=\"0.005\" duration=\"1\" frameRate=\"20\" maxParticles=\"1000000\"/>"
                 "<Water/><Nozzle position=\"0 0.5 0\" direction=\"0 -1 0\" radius=\"0.1\" speed=\"3\"/>"
                 "<Plane point=\"0 0 0\" normal=\"0 1 0\"/></Scene>");
  const std::string out = freshTempPath("oom_out");
  const SoakResult r = runShell("SOAK_MEMORY_LIMIT=2M " + std::string(SOAK_BINARY) + " run " + scene + " -o " + out +
                                " --device cpu --quiet --checkpoint-every 2");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("SOAK_MEMORY_LIMIT"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("soak run --resume " + out), std::string::npos) << r.output;
  const auto frames = pvdFiles(out + "/water.pvd");
  ASSERT_GE(frames.size(), 2u) << r.output;
  EXPECT_LT(frames.size(), 21u) << "the run was not stopped by the limit";
  for (const std::string& f : frames)
    EXPECT_NE(readWholeFile(out + "/" + f).find("</VTKFile>"), std::string::npos) << f << " is listed but not whole";
}

TEST(ProcessLimits, CpuThreadsFollowSlurmCpusPerTask) {
  {
    ScopedEnv slurm("SLURM_CPUS_PER_TASK", "1");
    std::string source;
    EXPECT_EQ(usableCpuCount(&source), 1);
    EXPECT_EQ(source, "SLURM_CPUS_PER_TASK");
  }
  const SoakResult r = runShell("unset OMP_NUM_THREADS; SLURM_CPUS_PER_TASK=1 " + std::string(SOAK_BINARY) + " run " +
                                waterCubeScene("threads", 0.1) + " -o " + freshTempPath("threads_out") +
                                " --device cpu");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("1 CPU threads (from SLURM_CPUS_PER_TASK)"), std::string::npos) << r.output;
}
