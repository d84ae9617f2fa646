#include "Cloth/StretchLimits.h"

#include <algorithm>
#include <tuple>

namespace soak {

namespace {

// Pairs 2, 4, 8, ... apart along a line of vertices whose prefix[k] is the
// rest length of the path from line[0] to line[k]; both views of each pair.
void addLinePairs(const std::vector<int>& line, const std::vector<double>& prefix, std::vector<StretchLimit>& out) {
  const int n = int(line.size());
  for (int span = 2; span < n; span *= 2)
    for (int i = 0; i + span < n; ++i) {
      const float rest = float(prefix[i + span] - prefix[i]);
      out.push_back({line[i], line[i + span], rest});
      out.push_back({line[i + span], line[i], rest});
    }
}

}  // namespace

std::vector<StretchLimit> sheetStretchLimits(const std::vector<Vec3>& rest, int columns, int rows) {
  // Per vertex, by span, then along +u, -u, +v, -v (the order the solve
  // sums a vertex's terms in).
  std::vector<StretchLimit> out;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i)
      for (int span = 2; span < std::max(columns, rows); span *= 2) {
        const int di[4] = {span, -span, 0, 0}, dj[4] = {0, 0, span, -span};
        for (int k = 0; k < 4; ++k) {
          const int i2 = i + di[k], j2 = j + dj[k];
          if (i2 < 0 || i2 >= columns || j2 < 0 || j2 >= rows) continue;
          const int a = j * columns + i, b = j2 * columns + i2;
          // The sheet is cut flat: the straight rest distance is the geodesic one.
          out.push_back({a, b, length(rest[a] - rest[b])});
        }
      }
  return out;
}

std::vector<StretchLimit> meshStretchLimits(const std::vector<Vec3>& rest, const ClothTopology& topo) {
  const int nv = int(rest.size());
  const int ne = int(topo.edges.size());
  std::vector<char> covered(ne, 0);
  std::vector<int> lineOf(nv, -1);  // the last line through each vertex
  std::vector<StretchLimit> out;
  std::vector<int> line;
  std::vector<double> lengths;  // lengths[k]: rest length of the edge line[k] - line[k + 1]
  // Extends the line at its back end along the straightest free edge.
  auto extend = [&](int id) {
    for (;;) {
      const int n = int(line.size());
      const int cur = line[n - 1], from = line[std::max(0, n - 3)];
      const Vec3 d = normalizedOrZero(rest[cur] - rest[from]);
      int bestEdge = -1, bestVertex = -1;
      float bestCos = kLineTurn;
      for (int k = topo.vertexEdgeStart[cur]; k < topo.vertexEdgeStart[cur + 1]; ++k) {
        const int e = topo.vertexEdges[k];
        const int m = topo.edges[e][0] == cur ? topo.edges[e][1] : topo.edges[e][0];
        if (covered[e] || lineOf[m] == id) continue;
        const float c = dot(normalizedOrZero(rest[m] - rest[cur]), d);
        if (c > bestCos) {
          bestCos = c;
          bestEdge = e;
          bestVertex = m;
        }
      }
      if (bestEdge < 0) return;
      covered[bestEdge] = 1;
      lineOf[bestVertex] = id;
      line.push_back(bestVertex);
      lengths.push_back(double(topo.edgeRestLength[bestEdge]));
    }
  };
  int id = 0;
  for (int e = 0; e < ne; ++e, ++id) {
    if (covered[e]) continue;
    covered[e] = 1;
    line = {topo.edges[e][0], topo.edges[e][1]};
    lengths = {double(topo.edgeRestLength[e])};
    lineOf[line[0]] = lineOf[line[1]] = id;
    extend(id);
    std::reverse(line.begin(), line.end());
    std::reverse(lengths.begin(), lengths.end());
    extend(id);
    std::vector<double> prefix(line.size(), 0.0);
    for (std::size_t k = 1; k < line.size(); ++k) prefix[k] = prefix[k - 1] + lengths[k - 1];
    addLinePairs(line, prefix, out);
  }
  // A pair on two lines keeps the shorter path (both bound the geodesic distance).
  std::sort(out.begin(), out.end(), [](const StretchLimit& p, const StretchLimit& q) {
    return std::tie(p.a, p.b, p.rest) < std::tie(q.a, q.b, q.rest);
  });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const StretchLimit& p, const StretchLimit& q) { return p.a == q.a && p.b == q.b; }),
            out.end());
  return out;
}

}  // namespace soak
