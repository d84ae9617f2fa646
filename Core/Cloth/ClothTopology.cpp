#include "Cloth/ClothTopology.h"

#include <Eigen/Core>
#include <algorithm>
#include <map>

namespace soak {

namespace {
Eigen::Vector3f toEigen(Vec3 v) { return {v.x, v.y, v.z}; }

// CSR lists: for each item, the vertices it touches.
template <std::size_t K>
void buildIncidence(int vertexCount, const std::vector<std::array<int, K>>& items, std::size_t use,
                    std::vector<int>& start, std::vector<int>& list) {
  start.assign(vertexCount + 1, 0);
  for (const auto& it : items)
    for (std::size_t c = 0; c < use; ++c) ++start[it[c] + 1];
  for (int v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
  list.assign(start[vertexCount], 0);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < items.size(); ++i)
    for (std::size_t c = 0; c < use; ++c) list[fill[items[i][c]]++] = static_cast<int>(i);
}
}  // namespace

ClothTopology buildClothTopology(const TriangleMesh& mesh) {
  ClothTopology t;
  const int nv = static_cast<int>(mesh.vertices.size());
  // Edge -> the triangles on it (at most two; validateClothMesh guarantees it).
  std::map<std::pair<int, int>, std::vector<int>> edgeTriangles;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int c = 0; c < 3; ++c) {
      int a = mesh.triangles[f][c], b = mesh.triangles[f][(c + 1) % 3];
      edgeTriangles[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  for (const auto& [edge, tris] : edgeTriangles) {
    const int a = edge.first, b = edge.second;
    t.edges.push_back({a, b});
    t.edgeRestLength.push_back((toEigen(mesh.vertices[a]) - toEigen(mesh.vertices[b])).norm());
    if (tris.size() != 2) continue;
    auto opposite = [&](int f) {
      for (int c = 0; c < 3; ++c) {
        int v = mesh.triangles[f][c];
        if (v != a && v != b) return v;
      }
      return -1;
    };
    std::array<int, 4> pair{a, b, opposite(tris[0]), opposite(tris[1])};
    t.bendPairs.push_back(pair);
    t.bendRestAngle.push_back(dihedralAngle(mesh.vertices[pair[0]], mesh.vertices[pair[1]], mesh.vertices[pair[2]],
                                            mesh.vertices[pair[3]]));
  }
  buildIncidence(nv, t.edges, 2, t.vertexEdgeStart, t.vertexEdges);
  buildIncidence(nv, t.bendPairs, 4, t.vertexBendStart, t.vertexBends);
  buildIncidence(nv, mesh.triangles, 3, t.vertexTriangleStart, t.vertexTriangles);
  return t;
}

TriangleMesh makeRectangularSheet(Vec3 origin, Vec3 axisU, Vec3 axisV, float sizeU, float sizeV, int cellsU,
                                  int cellsV) {
  TriangleMesh m;
  const Eigen::Vector3f o = toEigen(origin), u = toEigen(axisU).normalized(), v = toEigen(axisV).normalized();
  for (int j = 0; j <= cellsV; ++j)
    for (int i = 0; i <= cellsU; ++i) {
      Eigen::Vector3f p = o + u * (sizeU * float(i) / float(cellsU)) + v * (sizeV * float(j) / float(cellsV));
      m.vertices.push_back(Vec3(p.x(), p.y(), p.z()));
      m.uv.push_back({sizeU * float(i) / float(cellsU), sizeV * float(j) / float(cellsV)});
    }
  auto id = [&](int i, int j) { return j * (cellsU + 1) + i; };
  for (int j = 0; j < cellsV; ++j)
    for (int i = 0; i < cellsU; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  return m;
}

}  // namespace soak
