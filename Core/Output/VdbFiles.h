#pragma once
// Water as OpenVDB, for Houdini and Blender (issue 26): one .vdb per frame
// holding
//   "surface"    a narrow-band level set (float, GRID_LEVEL_SET, negative
//                inside, world units) of the relative density splat the
//                surface mesh uses (WaterSurface.h), at the same iso value;
//   "particles"  a VDB points grid: P, "v" (velocity, m/s), "pscale"
//                (the radius Houdini draws a point with, m) and "id"
//                (int32, stable across frames).
#include <string>
#include <vector>

#include "Base/Vec3.h"
#include "Output/WaterSurface.h"

namespace soak {

struct WaterVdbFrame {
  std::vector<Vec3> position, velocity;
  std::vector<int> id;
  std::vector<float> pointRadius;  // pscale (m)
  float spacing = 0.02f;  // r0 (m): the points grid's voxel is 2 r0
};

// Half-width of the level set's narrow band, in voxels on each side
// (OpenVDB's default, what Houdini's and Blender's tools expect).
constexpr float kVdbHalfWidthVoxels = 3.f;

// Writes `frame` to `path` through OpenVDB, under a temporary name renamed
// into place (the file is complete or absent). The level set is that of
// `splat` (splatRelativeDensity of the frame's particles with `s`) at
// s.iso; its voxel is the splat's cell (s.cellSize, or the coarser cell the
// splat takes for a very large grid).
void writeWaterVdb(const std::string& path, const WaterVdbFrame& frame, const RelativeDensityGrid& splat,
                   const WaterSurfaceSettings& s);

}  // namespace soak
