#include "Cloth/ConstraintColoring.h"

#include <stdexcept>

namespace soak {

ColouredOrder colourConstraints(const std::vector<int>& vertices, int arity, int vertexCount) {
  const int count = arity > 0 ? int(vertices.size()) / arity : 0;
  std::vector<int> colour(count, -1);
  // Colours already used at each vertex, as a list (cloth vertices touch few constraints).
  std::vector<std::vector<int>> used(vertexCount);
  int colours = 0;
  for (int k = 0; k < count; ++k) {
    int c = 0;
    for (;; ++c) {
      bool free = true;
      for (int a = 0; a < arity && free; ++a)
        for (int u : used[vertices[k * arity + a]])
          if (u == c) {
            free = false;
            break;
          }
      if (free) break;
    }
    colour[k] = c;
    for (int a = 0; a < arity; ++a) used[vertices[k * arity + a]].push_back(c);
    if (c + 1 > colours) colours = c + 1;
  }
  ColouredOrder out;
  out.colourStart.assign(colours + 1, 0);
  for (int k = 0; k < count; ++k) ++out.colourStart[colour[k] + 1];
  for (int c = 0; c < colours; ++c) out.colourStart[c + 1] += out.colourStart[c];
  out.order.resize(count);
  std::vector<int> fill(out.colourStart.begin(), out.colourStart.end() - 1);
  for (int k = 0; k < count; ++k) out.order[fill[colour[k]]++] = k;
  return out;
}

}  // namespace soak
