#pragma once
// A frame's meshes and particles as VTK objects in memory: what the .vtp
// writer writes, and what the Catalyst adaptor hands to ParaView.
#include <array>
#include <vector>

#include <vtkSmartPointer.h>

#include "Base/Vec3.h"
#include "Output/VtkFiles.h"  // PointArray

class vtkPolyData;

namespace soak {

// A triangle mesh as polygons, with its point arrays.
vtkSmartPointer<vtkPolyData> meshPolyData(const std::vector<Vec3>& points,
                                          const std::vector<std::array<int, 3>>& triangles,
                                          const std::vector<PointArray>& data);
// Particles as vertex cells, with their point arrays.
vtkSmartPointer<vtkPolyData> particlesPolyData(const std::vector<Vec3>& points, const std::vector<PointArray>& data);

}  // namespace soak
