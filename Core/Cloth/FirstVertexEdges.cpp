#include "Cloth/FirstVertexEdges.h"

#include <algorithm>

namespace soak {

FirstVertexEdges buildFirstVertexEdges(const std::vector<ClothTriangle>& triangles, int vertexCount) {
  std::vector<std::vector<int>> seconds(static_cast<std::size_t>(vertexCount));
  for (const ClothTriangle& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t.v[k], b = t.v[(k + 1) % 3];
      seconds[std::size_t(std::min(a, b))].push_back(std::max(a, b));
    }
  FirstVertexEdges out;
  out.start.assign(seconds.size() + 1, 0);
  for (std::size_t v = 0; v < seconds.size(); ++v) {
    std::vector<int>& s = seconds[v];
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());  // an inner edge is in two triangles
    out.other.insert(out.other.end(), s.begin(), s.end());
    out.start[v + 1] = int(out.other.size());
  }
  return out;
}

}  // namespace soak
