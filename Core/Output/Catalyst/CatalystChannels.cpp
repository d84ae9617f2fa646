#include "CatalystChannels.h"

#include <vtkPolyData.h>

#include "Output/FrameArrays.h"
#include "Output/VtkPolyData.h"

namespace soak {

CatalystChannels::CatalystChannels(const OutputLayout& layout) : layout_(layout) {
  names_.push_back("water");
  for (const ClothObject& c : layout_.cloths) names_.push_back("cloth_" + c.name);
  if (layout_.surfaceCellSize > 0.f) names_.push_back("water_surface");
}

std::vector<CatalystChannel> CatalystChannels::build(const SinkFrame& f) const {
  std::vector<CatalystChannel> out;
  const WaterArrays water = waterArrays(f.data);
  out.push_back({"water", particlesPolyData(water.points, water.data)});
  for (const ClothObject& c : layout_.cloths) {
    const ClothArrays cloth = clothArrays(f.data, c.phase, c.firstVertex, c.vertexCount, layout_.channelNames);
    out.push_back({"cloth_" + c.name, meshPolyData(cloth.points, c.localTriangles, cloth.data)});
  }
  if (layout_.surfaceCellSize > 0.f) {
    vtkSmartPointer<vtkPolyData> surface = vtkSmartPointer<vtkPolyData>::New();
    if (f.surface) surface->ShallowCopy(f.surface.get());
    out.push_back({"water_surface", surface});
  }
  return out;
}

}  // namespace soak
