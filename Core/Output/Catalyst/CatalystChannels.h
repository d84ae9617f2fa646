#pragma once
// The data a Catalyst script sees: one channel per collection the run
// writes, named as the .pvd files are (water, cloth_<name>, water_surface),
// with the same point arrays. A channel is also reachable by its file name
// (cloth_sheet.pvd): the name a source has in a script saved from the
// ParaView GUI after opening the run's files.
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "Output/FrameSink.h"
#include "Output/FrameSource.h"

class vtkPolyData;

namespace soak {

struct CatalystChannel {
  std::string name;
  vtkSmartPointer<vtkPolyData> data;
};

class CatalystChannels {
 public:
  explicit CatalystChannels(const OutputLayout& layout);
  // The channels' names, in order: water, each cloth, the water surface.
  const std::vector<std::string>& names() const { return names_; }
  // Water as vertex cells, each cloth as its triangle mesh, the surface
  // mesh where the scene has one (an empty mesh for a frame without water).
  std::vector<CatalystChannel> build(const SinkFrame& frame) const;

 private:
  OutputLayout layout_;
  std::vector<std::string> names_;
};

// The name a channel also answers to: its .pvd file's.
inline std::string channelFileName(const std::string& channel) { return channel + ".pvd"; }

}  // namespace soak
