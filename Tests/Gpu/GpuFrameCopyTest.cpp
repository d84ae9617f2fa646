// Frame copies on the GPU: staged on the compute stream, moved to pinned
// host memory on the copy stream while the next steps run.
#include <gtest/gtest.h>

#include "Support/FrameCopyChecks.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuFrameCopy, ADownloadKeepsTheValuesItWasQueuedWith) {
  SOAK_SKIP_WITHOUT_GPU();
  test::expectDownloadKeepsQueuedValues(Device::Cuda);
}

TEST(GpuFrameCopy, StatsFromTheFramesCopiesMatchTheDevicesReductions) {
  SOAK_SKIP_WITHOUT_GPU();
  test::expectFrameStatsMatchDeviceReductions(Device::Cuda);
}
