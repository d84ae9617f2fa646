#pragma once
// Cloth constraints derived from a triangle mesh (host side, built once and
// uploaded): stretch edges (Eq. 8), bending pairs (Eq. 9) and, per vertex,
// the constraints it takes part in (so a solver can gather per vertex, with
// no atomics).
#include <array>
#include <vector>

#include "Base/HostDevice.h"
#include "Base/Vec3.h"
#include "Scene/TriangleMesh.h"

namespace soak {

struct ClothTopology {
  // Unique edges (a < b) and their rest lengths l0 (Eq. 8).
  std::vector<std::array<int, 2>> edges;
  std::vector<float> edgeRestLength;
  // Pairs of triangles (x1, x3, x2) and (x1, x2, x4) sharing edge (x1, x2):
  // stored as {x1, x2, x3, x4} with the rest dihedral angle phi0 (Eq. 9).
  std::vector<std::array<int, 4>> bendPairs;
  std::vector<float> bendRestAngle;
  // Compressed lists per vertex: edges[vertexEdges[vertexEdgeStart[v] ..
  // vertexEdgeStart[v+1])] are the edges touching v; same for bends and triangles.
  std::vector<int> vertexEdgeStart, vertexEdges;
  std::vector<int> vertexBendStart, vertexBends;
  std::vector<int> vertexTriangleStart, vertexTriangles;
};

// Builds the topology; the mesh must pass validateClothMesh.
ClothTopology buildClothTopology(const TriangleMesh& mesh);

// A rectangular sheet of (cellsU + 1) x (cellsV + 1) vertices spanning
// origin + [0, 1] * sizeU * axisU + [0, 1] * sizeV * axisV (axes are unit
// vectors), each quad split into two triangles with alternating diagonals.
TriangleMesh makeRectangularSheet(Vec3 origin, Vec3 axisU, Vec3 axisV, float sizeU, float sizeV, int cellsU,
                                  int cellsV);

// Eq. 9 without phi0: acos(n1 . n2) with n1 = (x2-x1)x(x3-x1)/|...| and
// n2 = (x2-x1)x(x4-x1)/|...|. A flat pair (x3, x4 on opposite sides) gives pi.
SOAK_INLINE float dihedralAngle(Vec3 x1, Vec3 x2, Vec3 x3, Vec3 x4) {
  Vec3 e = x2 - x1;
  Vec3 n1 = normalizedOrZero(cross(e, x3 - x1));
  Vec3 n2 = normalizedOrZero(cross(e, x4 - x1));
  float c = minf(1.f, maxf(-1.f, dot(n1, n2)));
  return acosf(c);
}

}  // namespace soak
