#pragma once
#include <memory>
#include <vector>

#include "Backend/DownloadQueue.h"
#include "Registry/Module.h"
#include "Output/FrameSource.h"

namespace soak {

class Simulation;

// Queues copies of the particle arrays, channels, density and compression
// and of what modules name for their stats (Module::statsSources). Called
// on the stepping thread; on the GPU nothing waits for the device (the
// compression kernel and the copies are queued behind the step).
FrameCopy startFrameCopy(Simulation& sim, DownloadQueue& queue);

// Waits for the copies, unpacks them and gives the host memory back to
// `queue`. Any thread.
FrameData finishFrameCopy(FrameCopy&& copy, DownloadQueue& queue);

// A frame's stats.csv columns (counts, the water budget, density error,
// speeds, cloth strain, then each module's). Reads only `frame` and what
// setup fixed (cloth topology, modules' settings), so a writer thread may
// call it while `sim` steps on.
StatsRow frameStats(const Simulation& sim, const FrameData& frame);

}  // namespace soak
