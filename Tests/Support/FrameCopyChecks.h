#pragma once
// Checks of the frame copies (Backend/DownloadQueue.h, Simulation/FrameCopy.h),
// written once and run on each device by the CPU and the GPU suites.
#include "Backend/Device.h"

namespace soak::test {

// A download holds the arrays as they were when it was queued, though the
// device overwrites them at once; the queueing thread does not wait on the
// GPU; a larger download after it (the staging block grown) is right too.
void expectDownloadKeepsQueuedValues(Device d);

// A frame's stats, computed on the host from its copies, equal the device's
// own reductions of the same state (density error, stretch, held water,
// saturation) on a wetting scene.
void expectFrameStatsMatchDeviceReductions(Device d);

}  // namespace soak::test
