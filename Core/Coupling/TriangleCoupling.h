#pragma once
// The water-triangle constraint of Eq. 21: a water particle that would cross
// a cloth triangle between its old and predicted positions (or come closer
// than the coupling distance d) is put back on the side it came from.
#include "Cloth/ClothSystem.h"
#include "Neighbours/GridView.h"

namespace soak {

// Signed-side test and correction for one particle and one triangle.
// x0: particle's previous position, x: predicted position; a0..c0 and
// a..c: the triangle's previous and predicted vertices. Returns the
// displacement that satisfies C >= 0 (zero if the constraint holds or the
// particle does not pass through the triangle's interior).
// Whether q's projection onto the triangle's plane lies in triangle (a, b,
// c), grown by `margin` in barycentric units (the dot products with the
// edges see only q's part in the plane, so q need not be projected first).
// The barycentric coordinates are compared before their division by
// den > 0 (the same test without two divisions: most triangles a search
// tests are not hit, and the test is its cost).
SOAK_INLINE bool insideTriangle(Vec3 q, Vec3 a, Vec3 b, Vec3 c, float margin) {
  const Vec3 e0 = b - a, e1 = c - a, e2 = q - a;
  const float d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d20 = dot(e2, e0), d21 = dot(e2, e1);
  const float den = d00 * d11 - d01 * d01;
  if (den <= 0.f) return false;
  const float v = d11 * d20 - d01 * d21;  // times den
  const float w = d00 * d21 - d01 * d20;  // times den
  const float tol = -margin * den;
  return v >= tol && w >= tol && den - v - w >= tol;
}

// The triangle's snapshot (ClothSystem.h) from its vertices at the start of
// the step (a0, b0, c0) and now (a, b, c).
SOAK_INLINE TriangleSnapshot makeTriangleSnapshot(Vec3 a0, Vec3 b0, Vec3 c0, Vec3 a, Vec3 b, Vec3 c) {
  Vec3 n = cross(b - a, c - a);
  const float area2 = length(n);
  n = area2 >= 1e-14f ? n / area2 : Vec3(0.f, 0.f, 0.f);
  Vec3 n0 = normalizedOrZero(cross(b0 - a0, c0 - a0));
  if (dot(n0, n) <= 0.f) n0 = n;  // triangle flipped within a step: trust the new normal
  TriangleSnapshot t;
  t.q[0] = Float4(a.x, a.y, a.z, n.x);
  t.q[1] = Float4(n.y, n.z, a0.x, a0.y);
  t.q[2] = Float4(a0.z, n0.x, n0.y, n0.z);
  t.q[3] = Float4(b.x, b.y, b.z, c.x);
  t.q[4] = Float4(c.y, c.z, b0.x, b0.y);
  t.q[5] = Float4(b0.z, c0.x, c0.y, c0.z);
  return t;
}

SOAK_INLINE Vec3 triangleCouplingCorrection(Vec3 x0, Vec3 x, const TriangleSnapshot& tri, float d,
                                            float depthMargin = 0.5f) {
  const Vec3 zero(0.f, 0.f, 0.f);
  const Vec3 n = tri.n();
  // A triangle of (almost) no area has no normal: nothing to keep out of.
  if (n.x == 0.f && n.y == 0.f && n.z == 0.f) return zero;
  const Vec3 a = tri.a(), a0 = tri.a0(), n0 = tri.n0();
  // The side the particle came from (the +/- of Eq. 21).
  const float s0 = dot(x0 - a0, n0);
  const float sigma = s0 >= 0.f ? 1.f : -1.f;
  const float s1 = sigma * dot(x - a, n);
  const float C = s1 - d;
  if (C >= 0.f) return zero;
  const Vec3 b = tri.b(), c = tri.c();
  bool inside;
  if (s1 >= 0.f) {
    // Still on its side, closer than d: where it projects onto the plane.
    inside = insideTriangle(x, a, b, c, 1e-3f);
  } else {
    // It passed the plane. The constraint applies only if it passed through
    // the triangle: where the path meets the plane, both moving (the cloth
    // moves too, and can sweep through a particle that hardly moved), taken
    // at the fraction t where the signed distance changes sign. A point that
    // went around the triangle's edge crossed the plane outside it and is
    // left alone (putting back every end point that projects inside would
    // throw the vertices of a curling sheet centimetres). The
    // triangle is grown by a margin that grows with the depth reached: the
    // path's crossing through a crease between two triangles may fall just
    // outside each.
    const Vec3 b0 = tri.b0(), c0 = tri.c0();
    const float t = fabsf(s0) / (fabsf(s0) - s1);
    const Vec3 xt = x0 + (x - x0) * t;
    const Vec3 at = a0 + (a - a0) * t, bt = b0 + (b - b0) * t, ct = c0 + (c - c0) * t;
    // The margin grows with the depth over the triangle's size (the square
    // root of twice its area); vertex-triangle contact asks for none.
    const float margin =
        depthMargin > 0.f ? 1e-3f + depthMargin * (-s1) / sqrtf(length(cross(b - a, c - a))) : 1e-3f;
    inside = insideTriangle(xt, at, bt, ct, margin);
  }
  if (!inside) return zero;
  return n * (sigma * -C);
}

SOAK_INLINE Vec3 triangleCouplingCorrection(Vec3 x0, Vec3 x, Vec3 a0, Vec3 b0, Vec3 c0, Vec3 a, Vec3 b, Vec3 c,
                                            float d, float depthMargin = 0.5f) {
  return triangleCouplingCorrection(x0, x, makeTriangleSnapshot(a0, b0, c0, a, b, c), d, depthMargin);
}

// Distance from a point of the path x0 -> x within which every vertex of a
// triangle that matters to the particle lies: a triangle that x projects
// into (with the margin above), or that the path crosses, has its vertices
// within 1.5 edges + d of a point of the path.
SOAK_INLINE float triangleReach(float maxEdgeLength, float d) { return 1.5f * maxEdgeLength + d; }

// Whether y lies within `reach` of the path from x0 along `path` (its
// squared length `len2`): the point-segment distance.
SOAK_INLINE bool withinReachOfPath(Vec3 y, Vec3 x0, Vec3 path, float len2, float reach) {
  const float t = len2 > 0.f ? minf(maxf(dot(y - x0, path) / len2, 0.f), 1.f) : 0.f;
  return lengthSquared(y - (x0 + path * t)) <= reach * reach;
}

// Calls f(k, j) for the triangles whose first vertex is cloth slot j:
// k is the triangle's place in c.firstVertexTriangles (and c.triangleSnapshot).
template <class F>
SOAK_INLINE void forEachTriangleFirstAt(const ClothView& c, const ParticleView& p, int j, F&& f) {
  const int v = p.id[j];
  const int end = c.firstVertexTriangleStart[v + 1];
  for (int k = c.firstVertexTriangleStart[v]; k < end; ++k) f(k, j);
}

// The search around a path x0 -> x for the cloth whose triangles can
// matter: the box of cells to visit (a quarter cell wider than the reach:
// a slot is listed under the cell it was in when the grid was built, and
// cloth moves in its own solve after that), and the test of a candidate.
struct PathBox {
  Vec3 lo, hi;        // the cells to search
  Vec3 x0, path;      // the path: x0 -> x0 + path
  float len2, reach;  // |path|^2; the reach around it
  SOAK_INLINE PathBox(const GridView& g, Vec3 from, Vec3 to, float r) : x0(from), path(to - from), reach(r) {
    const float grow = r + 0.25f / g.invCellSize;
    lo = Vec3(minf(from.x, to.x) - grow, minf(from.y, to.y) - grow, minf(from.z, to.z) - grow);
    hi = Vec3(maxf(from.x, to.x) + grow, maxf(from.y, to.y) + grow, maxf(from.z, to.z) + grow);
    len2 = lengthSquared(path);
  }
  // Whether cloth slot j, at y, is a candidate.
  SOAK_INLINE bool near(Vec3 y) const { return withinReachOfPath(y, x0, path, len2, reach); }
};

// Calls f(j) for every cloth slot j within `reach` of the path x0 -> x
// (PathBox). With `lanes`, this lane's share of them (Base/Lanes.h).
template <class F>
SOAK_INLINE void forEachClothNearPath(const GridView& g, const ParticleView& p, Vec3 x0, Vec3 x, float reach,
                                      const Lanes& lanes, F&& f) {
  const PathBox box(g, x0, x, reach);
  forEachCandidateInBox(g, box.lo, box.hi, lanes, [&](int j) {
    if (!isCloth(p.phase[j])) return;
    if (box.near(p.predicted[j].xyz())) f(j);
  });
}

// Calls f(k, j) once for every cloth triangle that can matter to a point
// moving from x0 to x: k is its place in c.firstVertexTriangles (and
// c.triangleSnapshot), j the slot of its first vertex, from which it is
// visited; all three vertices lie within reach.
template <class F>
SOAK_INLINE void forEachTriangleNearPath(const GridView& g, const ParticleView& p, const ClothView& c, Vec3 x0, Vec3 x,
                                         const Lanes& lanes, F&& f) {
  const float reach = triangleReach(c.maxEdgeLength, 0.5f * c.maxThickness);
  forEachClothNearPath(g, p, x0, x, reach, lanes, [&](int j) { forEachTriangleFirstAt(c, p, j, f); });
}

// Refreshes c.triangleSnapshot from the particles' start-of-step and
// predicted positions; the searches below read it. With `onlyIf`, a
// device flag, the launch does nothing unless it is set.
void snapshotTriangles(Device d, ParticleView p, ClothView c, const int* onlyIf = nullptr);

// One pass of Eq. 21 over all water particles against the triangles of the
// cloth particles around them. `vertexStiffness` (per cloth vertex, may be
// null for 1) gives kappa_couple of a triangle as the mean of its vertices
// (Eq. 22 is this mean); the correction is scaled by Eq. 5 for `passes`.
// `g` is any grid that holds the cloth particles (the cloth's own is fastest).
// `movedFlag` is scratch of p.count ints: after the first pass only the water a
// pass moved is taken again. The passes move water only, so a particle no
// triangle corrected sees the same triangles from the same place in the
// next pass, and again nothing would correct it (the same bits as taking
// it again). On the GPU a particle takes lanesFor(count, minLanes) lanes,
// or exactly `exactLanes` where that is > 0 (1: the one-lane walk; tests
// compare the group sizes).
void projectWaterOutOfCloth(Device d, ParticleView p, GridView g, ClothView c, const float* vertexStiffness,
                            int passes, int* movedFlag, int minLanes = 1, int exactLanes = 0);

}  // namespace soak
