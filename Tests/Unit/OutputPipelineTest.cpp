// Frames are written off the stepping thread (Output/FrameWriter.h): a
// capture returns while a slow writer is still writing, frames are listed
// in order once all their files are on disk, and a full queue makes a step
// wait and says so.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <regex>
#include <string>

#include "Output/FrameWriter.h"
#include "SoakProcess.h"
#include "Support/TestScenes.h"

using namespace soak;
using namespace soak::test;

namespace {

const char* kScene = R"(<Scene>
  <WaterBlock min="0 0.1 0" max="0.1 0.2 0.1"/>
  <Cloth cellsU="8" cellsV="8" width="0.3" height="0.3" origin="-0.1 0 -0.1" axisU="1 0 0" axisV="0 0 1"/>
  <Plane point="0 -0.2 0"/>
</Scene>
)";

int pvdEntries(const std::string& path) {
  const std::string pvd = readWholeFile(path);
  const std::regex entry("<DataSet ");
  return int(std::distance(std::sregex_iterator(pvd.begin(), pvd.end(), entry), std::sregex_iterator()));
}

// A writer into a fresh folder with one background thread, `queued` frames
// of queue, slowed to `delay` seconds a frame.
std::unique_ptr<FrameWriter> slowWriter(const std::string& dir, int queued, double delay) {
  OutputSettings settings;
  settings.writerThreads = 1;
  settings.queuedFrames = queued;
  auto writer = std::make_unique<FrameWriter>(dir, kScene, FrameWriter::Start::Fresh, settings);
  writer->setWriteDelayForTesting(delay);
  return writer;
}

double secondsOf(const std::function<void()>& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// A writer slowed to 0.5 s a frame: the six captures each return in far less
// (they only copy arrays), while the frames are still being written; flush()
// then finds all six on disk and listed, in order.
TEST(OutputPipeline, AStepDoesNotWaitForASlowWriter) {
  TestRegistry reg;
  auto sim = makeSimulation(kScene, Device::Cpu, reg);
  const std::string dir = freshTempPath("output_slow_writer");
  constexpr double kDelay = 0.5;
  const auto writerOwner = slowWriter(dir, 8, kDelay);
  FrameWriter& writer = *writerOwner;
  double slowest = 0.0;
  for (int f = 0; f < 6; ++f) {
    for (int s = 0; s < 3; ++s) sim->step();
    slowest = std::max(slowest, secondsOf([&] { writer.writeFrame(*sim, f, 0.0); }));
  }
  std::printf("slowest capture %.4f s against a writer taking %.1f s a frame; %d of 6 frames on disk after the loop\n",
              slowest, kDelay, writer.framesWritten());
  EXPECT_LT(slowest, 0.5 * kDelay) << "a capture waited for the writer";
  EXPECT_LE(writer.framesWritten(), 2) << "frames were written on the stepping thread";
  EXPECT_FALSE(writer.waitedForDisk());
  writer.flush();
  EXPECT_EQ(writer.framesWritten(), 6);
  EXPECT_EQ(pvdEntries(dir + "/water.pvd"), 6);
  EXPECT_EQ(pvdEntries(dir + "/cloth_cloth.pvd"), 6);
  for (int f = 0; f < 6; ++f) {
    char name[64];
    std::snprintf(name, sizeof(name), "/water/water_%06d.vtu", f);
    EXPECT_TRUE(pathExists(dir + name)) << name;
  }
}

// With two frames allowed in the queue, the third capture waits for the
// writer (bounded memory) and the writer reports that steps waited.
TEST(OutputPipeline, AFullQueueMakesTheStepWaitAndSaysSo) {
  TestRegistry reg;
  auto sim = makeSimulation(kScene, Device::Cpu, reg);
  const std::string dir = freshTempPath("output_full_queue");
  constexpr double kDelay = 0.4;
  const auto writerOwner = slowWriter(dir, 2, kDelay);
  FrameWriter& writer = *writerOwner;
  writer.writeFrame(*sim, 0, 0.0);
  writer.writeFrame(*sim, 1, 0.0);
  const double third = secondsOf([&] { writer.writeFrame(*sim, 2, 0.0); });
  EXPECT_GT(third, 0.5 * kDelay) << "the queue let a third frame in";
  EXPECT_TRUE(writer.waitedForDisk());
  writer.flush();
  EXPECT_EQ(pvdEntries(dir + "/water.pvd"), 3);
}
