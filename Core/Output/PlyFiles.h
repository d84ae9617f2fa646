#pragma once
// Cloth as binary PLY, for Blender and Houdini (issue 26): one file per
// frame and cloth. The format is a text header and packed records, written
// here directly: VTK's writer class cannot carry arbitrary vertex
// properties, and its PLY library keeps global state that would let only
// one writer thread write at a time. The tests read the files back through
// that library. Vertex properties:
//   x y z              position (m)
//   vx vy vz           velocity (m/s)
//   <channel>          every particle channel (saturation, held_water, ...)
//   red green blue     uchar, from the colour channel (white dry, 0, to
//                      deep blue, 1), when one is named
// and faces as vertex_indices lists. Little-endian binary.
#include <array>
#include <string>
#include <vector>

#include "Base/Vec3.h"
#include "Output/VtkFiles.h"

namespace soak {

struct ClothPlyFrame {
  std::vector<Vec3> position, velocity;
  std::vector<std::array<int, 3>> triangles;
  std::vector<PointArray> channels;  // one component each, one value per vertex
  int colourChannel = -1;            // index into channels; -1: no colour
};

// The file's bytes.
std::string clothPlyBytes(const ClothPlyFrame& frame);

// Writes the frame to `path` under a temporary name renamed into place.
void writeClothPly(const std::string& path, const ClothPlyFrame& frame);

// The vertex colour of a value in [0, 1] (clamped): white to deep blue,
// as a wet patch darkens fabric.
std::array<unsigned char, 3> wetnessColour(float value);

}  // namespace soak
