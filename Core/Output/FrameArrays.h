#pragma once
// A frame's particles as the output files name them: the water's points and
// point arrays (water.pvd) and each cloth's (cloth_<name>.pvd). The frame
// writer and the Catalyst adaptor both take them from here, so a pipeline
// in situ sees the arrays the files hold.
#include <cstddef>
#include <string>
#include <vector>

#include "Base/Vec3.h"
#include "Output/FrameData.h"
#include "Output/VtkFiles.h"  // PointArray

namespace soak {

// Water particles sorted by id (frames list them in a stable order), with
// velocity, mass, radius, id and density; `slots` are their indices in the
// frame's arrays.
struct WaterArrays {
  std::vector<std::size_t> slots;
  std::vector<Vec3> points;
  std::vector<PointArray> data;
};
WaterArrays waterArrays(const FrameData& frame);

// One cloth's vertices in mesh order (vertex k is the cloth's particle with
// id firstVertex + k), with velocity and every channel, by name.
struct ClothArrays {
  std::vector<Vec3> points;
  std::vector<PointArray> data;
};
ClothArrays clothArrays(const FrameData& frame, int phase, int firstVertex, int vertexCount,
                        const std::vector<std::string>& channelNames);

}  // namespace soak
