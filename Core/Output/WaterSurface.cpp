#include "Output/WaterSurface.h"

#include <algorithm>
#include <cmath>

#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "Fluid/SphKernels.h"

namespace soak {

RelativeDensityGrid splatRelativeDensity(const std::vector<Vec3>& x, const std::vector<float>& mass,
                                         const std::vector<float>& radius, float rho0, const WaterSurfaceSettings& s) {
  RelativeDensityGrid grid;
  if (x.empty() || !(s.cellSize > 0.f)) return grid;
  float hMax = 0.f;
  Vec3 lo = x[0], hi = x[0];
  for (std::size_t i = 0; i < x.size(); ++i) {
    hMax = std::max(hMax, radius[i]);
    lo = Vec3(std::min(lo.x, x[i].x), std::min(lo.y, x[i].y), std::min(lo.z, x[i].z));
    hi = Vec3(std::max(hi.x, x[i].x), std::max(hi.y, x[i].y), std::max(hi.z, x[i].z));
  }
  lo = lo - Vec3(hMax, hMax, hMax);
  hi = hi + Vec3(hMax, hMax, hMax);
  // A coarser cell where the grid would be too large (a splash across the domain).
  double cell = s.cellSize;
  auto cells = [&](double c) {
    return double(std::ceil((hi.x - lo.x) / c) + 1) * double(std::ceil((hi.y - lo.y) / c) + 1) *
           double(std::ceil((hi.z - lo.z) / c) + 1);
  };
  while (cells(cell) > double(s.maxCells)) cell *= 1.25;
  const int nx = int(std::ceil((hi.x - lo.x) / cell)) + 1, ny = int(std::ceil((hi.y - lo.y) / cell)) + 1,
            nz = int(std::ceil((hi.z - lo.z) / cell)) + 1;
  grid.lo = lo;
  grid.cell = cell;
  grid.nx = nx;
  grid.ny = ny;
  grid.nz = nz;
  std::vector<float>& field = grid.values;
  field.assign(std::size_t(nx) * ny * nz, 0.f);
  const float inv = float(1.0 / cell);
  // Splat particle by particle; z slabs in parallel would race at their
  // borders, so the loop is serial (a few million kernel evaluations).
  for (std::size_t i = 0; i < x.size(); ++i) {
    const float h = radius[i], share = mass[i] / rho0;
    const int i0 = std::max(0, int(std::floor((x[i].x - h - lo.x) * inv))),
              i1 = std::min(nx - 1, int(std::ceil((x[i].x + h - lo.x) * inv)));
    const int j0 = std::max(0, int(std::floor((x[i].y - h - lo.y) * inv))),
              j1 = std::min(ny - 1, int(std::ceil((x[i].y + h - lo.y) * inv)));
    const int k0 = std::max(0, int(std::floor((x[i].z - h - lo.z) * inv))),
              k1 = std::min(nz - 1, int(std::ceil((x[i].z + h - lo.z) * inv)));
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        for (int ii = i0; ii <= i1; ++ii) {
          const Vec3 g(lo.x + float(ii * cell), lo.y + float(j * cell), lo.z + float(k * cell));
          const float r2 = lengthSquared(g - x[i]);
          if (r2 < h * h) field[(std::size_t(k) * ny + j) * nx + ii] += share * poly6(r2, h);
        }
  }
  return grid;
}

vtkSmartPointer<vtkPolyData> buildWaterSurface(const std::vector<Vec3>& x, const std::vector<float>& mass,
                                               const std::vector<float>& radius, float rho0,
                                               const WaterSurfaceSettings& s) {
  return contourRelativeDensity(splatRelativeDensity(x, mass, radius, rho0, s), s.iso);
}

vtkSmartPointer<vtkPolyData> contourRelativeDensity(const RelativeDensityGrid& grid, float iso) {
  if (grid.values.empty()) return vtkSmartPointer<vtkPolyData>::New();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(grid.nx, grid.ny, grid.nz);
  image->SetOrigin(grid.lo.x, grid.lo.y, grid.lo.z);
  image->SetSpacing(grid.cell, grid.cell, grid.cell);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName("relative_density");
  values->SetNumberOfValues(vtkIdType(grid.values.size()));
  for (std::size_t n = 0; n < grid.values.size(); ++n) values->SetValue(vtkIdType(n), grid.values[n]);
  image->GetPointData()->SetScalars(values);
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputData(image);
  contour->SetValue(0, iso);
  contour->ComputeNormalsOn();
  contour->ComputeScalarsOff();
  contour->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(contour->GetOutput());
  return out;
}

}  // namespace soak
