#pragma once
// What the frame writer needs of whatever it writes (the simulation
// implements it): the layout fixed at setup, and each frame as a queued
// copy to the host and as a stats row. The writer reads nothing else.
#include <memory>
#include <string>
#include <vector>

#include "Backend/Device.h"
#include "Backend/DownloadQueue.h"
#include "Cloth/ClothSystem.h"
#include "Output/FrameData.h"
#include "Registry/Module.h"
#include "Fluid/WaterSettings.h"

namespace soak {

// An output frame queued for copying to the host: what startFrameCopy took
// on the stepping thread, and where its arrays will be.
struct FrameCopy {
  std::unique_ptr<DownloadQueue::Transfer> transfer;
  FrameData scalars;  // step, time and the water budget; no arrays yet
  int count = 0, densitySlots = 0, channels = 0;
  bool compression = false;
  std::vector<int> moduleParts;  // parts each module named, in module order
};

// What does not change during a run: the particle channels' names, the
// cloth objects (their meshes), the water surface's splat and the water.
struct OutputLayout {
  std::vector<std::string> channelNames;
  std::vector<ClothObject> cloths;
  float surfaceCellSize = 0.f, surfaceIso = 0.5f;  // <WaterSurface>; cell 0: none
  WaterSettings water;
};

class FrameSource {
 public:
  virtual Device frameDevice() const = 0;
  virtual OutputLayout outputLayout() const = 0;
  // On the stepping thread: queues the copies (nothing waits for them).
  virtual FrameCopy startFrameCopy(DownloadQueue& queue) = 0;
  // Any thread: waits for the copies and unpacks them.
  virtual FrameData finishFrameCopy(FrameCopy&& copy, DownloadQueue& queue) const = 0;
  // Any thread: a frame's stats.csv columns from the frame alone and what
  // setup fixed, while the source steps on.
  virtual StatsRow frameStats(const FrameData& frame) const = 0;

 protected:
  ~FrameSource() = default;
};

}  // namespace soak
