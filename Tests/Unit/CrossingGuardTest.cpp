// The cloth crossing guard (Cloth/CrossingGuard.h): no edge ends a sub-step
// through a triangle it was not through at the start.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "Cloth/CrossingGuard.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(CrossingGuard, SegmentThroughTheTriangleCrossesOneBesideItOrAlongItDoesNot) {
  const Vec3 a(0.f, 0.f, 0.f), b(1.f, 0.f, 0.f), c(0.f, 0.f, 1.f);
  EXPECT_TRUE(segmentCrossesTriangle(Vec3(0.2f, 1.f, 0.2f), Vec3(0.2f, -1.f, 0.2f), a, b, c));
  EXPECT_TRUE(segmentCrossesTriangle(Vec3(0.2f, -1.f, 0.2f), Vec3(0.3f, 1.f, 0.1f), a, c, b));  // either winding
  EXPECT_FALSE(segmentCrossesTriangle(Vec3(0.8f, 1.f, 0.8f), Vec3(0.8f, -1.f, 0.8f), a, b, c));  // beside it
  EXPECT_FALSE(segmentCrossesTriangle(Vec3(0.2f, 1.f, 0.2f), Vec3(0.2f, 0.1f, 0.2f), a, b, c));  // stops short
  EXPECT_FALSE(segmentCrossesTriangle(Vec3(-1.f, 0.f, 0.2f), Vec3(1.f, 0.f, 0.2f), a, b, c));    // in its plane
}

namespace {
// Sheet A (8 x 2 cm, standing on its long edge) falls onto sheet B (2 x 8
// cm, flat and pinned) laid across it like a plus sign. No vertex of either
// lies over the other's triangles, and no two vertices come within the
// thickness, so neither particle contact nor the vertex-triangle test sees
// the sheets meet: only their edges pass through each other's triangles
// (B's two long edges through A, once A's lower edge is below B).
struct Crossing {
  float meanHeightOfA = 0.f;  // m; B lies at 0
  int crossings = 0;          // edges of one sheet through a triangle of the other, at the end
};

Crossing dropAcross(int guardRounds) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothSubsteps='4' clothIterations='8' clothSubstepTravel='0' crossingGuardRounds='" +
          std::to_string(guardRounds) +
          "'/>"
          "<Cloth name='a' model='chebyshev' origin='-0.04 0.005 -0.01' axisU='1 0 0' axisV='0 1 0' width='0.08' "
          "height='0.02' cellsU='1' cellsV='1' thickness='0.002'/>"
          "<Cloth name='b' model='chebyshev' origin='0 0 -0.04' axisU='1 0 0' axisV='0 0 1' width='0.02' "
          "height='0.08' cellsU='1' cellsV='1' thickness='0.002' pinCorners='u0v0 u1v0 u0v1 u1v1'/></Scene>",
      Device::Cpu, reg);
  for (int s = 0; s < 20; ++s) sim->step();
  const std::vector<Float4> x = sim->particles.downloadPositions();
  const std::vector<int> slot = sim->cloth.vertexSlots(sim->particles.downloadIds(), sim->particles.downloadPhases());
  const auto at = [&](int v) { return x[std::size_t(slot[std::size_t(v)])].xyz(); };
  const std::vector<ClothObject>& objects = sim->cloth.objects();
  Crossing out;
  for (int v = 0; v < objects[0].vertexCount; ++v) out.meanHeightOfA += at(objects[0].firstVertex + v).y;
  out.meanHeightOfA /= float(objects[0].vertexCount);
  for (int e = 0; e < 2; ++e) {
    const ClothObject& edgeSheet = objects[std::size_t(e)];
    const ClothObject& triangleSheet = objects[std::size_t(1 - e)];
    for (const auto& te : edgeSheet.localTriangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3 p0 = at(edgeSheet.firstVertex + te[std::size_t(k)]);
        const Vec3 p1 = at(edgeSheet.firstVertex + te[std::size_t((k + 1) % 3)]);
        for (const auto& t : triangleSheet.localTriangles)
          out.crossings += segmentCrossesTriangle(p0, p1, at(triangleSheet.firstVertex + t[0]),
                                                  at(triangleSheet.firstVertex + t[1]),
                                                  at(triangleSheet.firstVertex + t[2]))
                               ? 1
                               : 0;
      }
  }
  return out;
}
}  // namespace

TEST(CrossingGuard, ASheetFallingEdgesFirstThroughAnotherIsHeldOnItsSide) {
  const Crossing unguarded = dropAcross(0), guarded = dropAcross(3);
  std::printf("sheet dropped across another for 0.3 s: mean height %.4f m with no guard (%d crossings), %.4f m "
              "guarded (%d)\n",
              unguarded.meanHeightOfA, unguarded.crossings, guarded.meanHeightOfA, guarded.crossings);
  // Unguarded, A falls freely through B: 0.015 - g t^2 / 2 = -0.43 m.
  EXPECT_LT(unguarded.meanHeightOfA, -0.3f);
  // Guarded, it stands on B's edges (its middle 1 cm above them; it may
  // lean) and nothing passes through.
  EXPECT_GT(guarded.meanHeightOfA, -0.005f);
  EXPECT_EQ(guarded.crossings, 0);
}
