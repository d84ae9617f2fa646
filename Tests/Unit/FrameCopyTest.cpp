// Frame copies on the CPU (the GPU suite runs the same checks on the device).
#include <gtest/gtest.h>

#include "Support/FrameCopyChecks.h"

using namespace soak;

TEST(FrameCopy, ADownloadKeepsTheValuesItWasQueuedWith) { test::expectDownloadKeepsQueuedValues(Device::Cpu); }

TEST(FrameCopy, StatsFromTheFramesCopiesMatchTheDevicesReductions) {
  test::expectFrameStatsMatchDeviceReductions(Device::Cpu);
}
