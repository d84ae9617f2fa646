#pragma once
// A water surface from the particles (issue 5; the paper renders one with a
// cell size of about 0.7 r0): each particle splats its share of the rest
// density, m_i / rho0 W(x - x_i, h_i), onto a regular grid, and the surface
// is the level set where that sum, the density relative to rest, equals
// `iso`. The mesh (flying edges, through VTK) and the OpenVDB level set
// (VdbFiles.h) are both taken from this one splat.
#include <vector>

#include <vtkSmartPointer.h>

#include "Base/Vec3.h"
#include "Output/OutputSettings.h"  // WaterSurfaceSettings

class vtkPolyData;

namespace soak {

// The relative density on grid points lo + (i, j, k) * cell, x fastest:
// values[(k * ny + j) * nx + i]. The grid covers every particle's support.
struct RelativeDensityGrid {
  Vec3 lo;
  double cell = 0.0;
  int nx = 0, ny = 0, nz = 0;
  std::vector<float> values;
};

// positions, masses and support radii of the water particles; rho0 the rest
// density. Empty (nx = 0) when there is no water.
RelativeDensityGrid splatRelativeDensity(const std::vector<Vec3>& x, const std::vector<float>& mass,
                                         const std::vector<float>& radius, float rho0, const WaterSurfaceSettings& s);

// The mesh where a splat equals `iso` (flying edges).
vtkSmartPointer<vtkPolyData> contourRelativeDensity(const RelativeDensityGrid& grid, float iso);

// The surface mesh of splatRelativeDensity at s.iso.
vtkSmartPointer<vtkPolyData> buildWaterSurface(const std::vector<Vec3>& x, const std::vector<float>& mass,
                                               const std::vector<float>& radius, float rho0,
                                               const WaterSurfaceSettings& s);

}  // namespace soak
