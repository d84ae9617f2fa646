#include "Output/FrameArrays.h"

#include <algorithm>

#include "Particles/Phase.h"

namespace soak {

WaterArrays waterArrays(const FrameData& c) {
  WaterArrays w;
  for (std::size_t i = 0; i < c.phase.size(); ++i)
    if (isWater(c.phase[i])) w.slots.push_back(i);
  std::sort(w.slots.begin(), w.slots.end(), [&](std::size_t a, std::size_t b) { return c.id[a] < c.id[b]; });
  w.points.resize(w.slots.size());
  PointArray v{"velocity", 3, {}}, m{"mass", 1, {}}, r{"radius", 1, {}}, ids{"id", 1, {}}, rho{"density", 1, {}};
  for (std::size_t k = 0; k < w.slots.size(); ++k) {
    const std::size_t i = w.slots[k];
    w.points[k] = c.position[i].xyz();
    v.values.insert(v.values.end(), {c.velocity[i].x, c.velocity[i].y, c.velocity[i].z});
    m.values.push_back(c.mass[i]);
    r.values.push_back(c.radius[i]);
    ids.values.push_back(static_cast<float>(c.id[i]));
    rho.values.push_back(c.density[i]);
  }
  w.data = {std::move(v), std::move(m), std::move(r), std::move(ids), std::move(rho)};
  return w;
}

ClothArrays clothArrays(const FrameData& c, int phase, int firstVertex, int vertexCount,
                        const std::vector<std::string>& channelNames) {
  const std::size_t n = std::size_t(vertexCount);
  ClothArrays out;
  out.points.resize(n);
  out.data.push_back({"velocity", 3, std::vector<float>(3 * n)});
  for (const std::string& name : channelNames) out.data.push_back({name, 1, std::vector<float>(n)});
  for (std::size_t i = 0; i < c.phase.size(); ++i) {
    if (c.phase[i] != phase) continue;
    const std::size_t local = std::size_t(c.id[i] - firstVertex);
    out.points[local] = c.position[i].xyz();
    out.data[0].values[3 * local] = c.velocity[i].x;
    out.data[0].values[3 * local + 1] = c.velocity[i].y;
    out.data[0].values[3 * local + 2] = c.velocity[i].z;
    for (std::size_t k = 0; k < channelNames.size(); ++k) out.data[k + 1].values[local] = c.channels[k][i];
  }
  return out;
}

}  // namespace soak
