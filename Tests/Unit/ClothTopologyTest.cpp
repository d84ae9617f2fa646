#include <gtest/gtest.h>

#include <cmath>

#include "Cloth/ClothTopology.h"

using namespace soak;

TEST(ClothTopology, SheetCountsMatchCombinatorics) {
  const int n = 7;
  TriangleMesh m = makeRectangularSheet(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), 1.4f, 1.4f, n, n);
  validateClothMesh(m, "sheet");
  EXPECT_EQ(m.vertices.size(), std::size_t((n + 1) * (n + 1)));
  EXPECT_EQ(m.triangles.size(), std::size_t(2 * n * n));
  ClothTopology t = buildClothTopology(m);
  EXPECT_EQ(t.edges.size(), std::size_t(3 * n * n + 2 * n));      // horizontal + vertical + diagonals
  EXPECT_EQ(t.bendPairs.size(), std::size_t(3 * n * n - 2 * n));  // every interior edge
  for (float l : t.edgeRestLength) {
    const bool axis = std::fabs(l - 0.2f) < 1e-5f, diagonal = std::fabs(l - 0.2f * std::sqrt(2.f)) < 1e-5f;
    EXPECT_TRUE(axis || diagonal) << l;
  }
  // A flat sheet: every rest dihedral angle is pi (Eq. 9 convention).
  for (float phi : t.bendRestAngle) EXPECT_NEAR(phi, float(M_PI), 1e-3f);
}

TEST(ClothTopology, IncidenceListsAreComplete) {
  TriangleMesh m = makeRectangularSheet(Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), 0.5f, 0.3f, 5, 3);
  ClothTopology t = buildClothTopology(m);
  const int nv = int(m.vertices.size());
  ASSERT_EQ(int(t.vertexEdgeStart.size()), nv + 1);
  std::vector<int> edgeSeen(t.edges.size(), 0), bendSeen(t.bendPairs.size(), 0);
  for (int v = 0; v < nv; ++v) {
    for (int k = t.vertexEdgeStart[v]; k < t.vertexEdgeStart[v + 1]; ++k) {
      const auto& e = t.edges[t.vertexEdges[k]];
      EXPECT_TRUE(e[0] == v || e[1] == v);
      ++edgeSeen[t.vertexEdges[k]];
    }
    for (int k = t.vertexBendStart[v]; k < t.vertexBendStart[v + 1]; ++k) ++bendSeen[t.vertexBends[k]];
  }
  for (int s : edgeSeen) EXPECT_EQ(s, 2);
  for (int s : bendSeen) EXPECT_EQ(s, 4);
  EXPECT_EQ(t.vertexTriangleStart[nv], int(3 * m.triangles.size()));
}

TEST(ClothTopology, DihedralAngleOfAFold) {
  // Two triangles on edge x1-x2 folded to a right angle.
  Vec3 x1(0, 0, 0), x2(1, 0, 0), x3(0.5f, 1, 0), x4(0.5f, 0, 1);
  EXPECT_NEAR(dihedralAngle(x1, x2, x3, x4), float(M_PI) / 2.f, 1e-5f);
  EXPECT_NEAR(dihedralAngle(x1, x2, x3, Vec3(0.5f, -1, 0)), float(M_PI), 1e-3f);
}
