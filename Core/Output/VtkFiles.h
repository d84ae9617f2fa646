#pragma once
// VTK XML files (binary appended, compressed as Output.compression says)
// through the VTK library.
#include <array>
#include <string>
#include <vector>

#include "Base/Vec3.h"
#include "Output/OutputSettings.h"

class vtkPolyData;

namespace soak {

struct PointArray {
  std::string name;
  int components = 1;
  std::vector<float> values;  // size = points * components
};

// Particles as an unstructured grid of vertex cells (ParaView can glyph them).
void writeParticlesVtu(const std::string& path, const std::vector<Vec3>& points, const std::vector<PointArray>& data,
                       Compression compression);

// A triangle mesh as poly data.
void writeMeshVtp(const std::string& path, const std::vector<Vec3>& points,
                  const std::vector<std::array<int, 3>>& triangles, const std::vector<PointArray>& data,
                  Compression compression);

// Any poly data (e.g. the water surface), written the same way.
void writePolyDataVtp(const std::string& path, vtkPolyData* poly, Compression compression);

// Writes `content` to `path` atomically (temporary file, rename), so a
// reader, or a run killed at any moment, never sees a half-written file.
// `durable` also syncs the file to the disk before the rename (checkpoints:
// they must survive a power cut); a .pvd need not, since the frame files it
// lists are not synced either, and a sync per frame would set the pace of
// the writers.
void writeFileAtomically(const std::string& path, const std::string& content, bool durable = true);

}  // namespace soak
