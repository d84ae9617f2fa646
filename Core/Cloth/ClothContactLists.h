#pragma once
// Candidate pairs for cloth contact, found once a step and read by every
// contact pass of every cloth sub-step: particle contact and vertex-triangle
// contact (ClothContact.h).
//
// A contact pass walking the 27 cells of the cloth grid visits 150-300
// cloth particles (cells are the water's support radius, 4 cm; a sheet's
// vertices are 1 cm apart), of which a handful come within the contact
// distance c_ij = (th_i + th_j) / 2; the vertex-triangle pass walks a box
// of cells around each vertex's path for the triangles whose vertices lie
// within the triangle reach t = 1.5 l_max + th_max / 2 of it
// (TriangleCoupling.h). Over one step a pair can only touch if it starts
// close: its distance at the start of the step, |x_i - x_j|, is at most
// the reach plus how far the two move. The lists keep, for each cloth
// particle, the cloth particles j with
//
//     |x_i - x_j| < max(3 c_ij, t) + 3 (|v_i| + |v_j|) dt     (x, v at the step's start)
//
// in the grid's order. Measured on every particle contact that acted
// (small fig9b 2.5 s, fig3b 2 s on chebyshev 8 x 12, CPU), the pair's start
// distance was at most 0.35 of 3 c_ij + 3 (|v_i| + |v_j|) dt; on a sheet
// crumpling onto the floor (ClothContactListsTest), every pair that ended a
// step within 1.5 c_ij had started within 0.54 of it.
//
// A second list per cloth particle holds the triangles vertex-triangle
// contact reads: those whose first vertex is a candidate, in the
// candidates' order, less the particle's own surface (a triangle of its own
// cloth sharing a vertex with one of its own triangles: on a sheet about a
// third of the candidates' triangles). The own-surface test is topology, so
// it is done here once a step instead of in every pass of every sub-step.
//
// An item without a list (past the buffer's capacity, PairLists.h) walks
// the grid and applies the same tests to the same start positions, so it
// sees the same candidates in the same order: on one lane (the CPU) the
// contact sums have the same bits whether or not an item got a list, and
// the lists' sizing need not be kept by checkpoints.
#include "Cloth/ClothSystem.h"
#include "Cloth/ForEachClothParticle.h"
#include "Coupling/TriangleCoupling.h"
#include "Neighbours/GridView.h"
#include "Neighbours/PairLists.h"
#include "Particles/ParticleState.h"

namespace soak {

constexpr float kContactReachDistances = 3.f;  // c_ij in the reach above
constexpr float kContactReachMotion = 3.f;     // (|v_i| + |v_j|) dt in it

// What the test reads: positions, velocities, phases and vertex ids of the
// particles at the step's start (the phases and ids hold for the whole step).
struct ClothContactStep {
  const Float4* position = nullptr;
  const Vec3* velocity = nullptr;
  const int* phase = nullptr;
  const int* id = nullptr;
  float dt = 0.f;
};

// Whether cloth particle j is a contact candidate of cloth particle i (slots).
SOAK_INLINE bool mayTouchThisStep(const ClothContactStep& s, const ClothView& c, int i, int j) {
  if (j == i || !isCloth(s.phase[j])) return false;
  const int vi = s.id[i], vj = s.id[j];
  const float contact = 0.5f * (c.thickness[vi] + c.thickness[vj]);
  const float reach = maxf(kContactReachDistances * contact, triangleReach(c.maxEdgeLength, 0.5f * c.maxThickness)) +
                      kContactReachMotion * (length(s.velocity[i]) + length(s.velocity[j])) * s.dt;
  return lengthSquared(s.position[i].xyz() - s.position[j].xyz()) < reach * reach;
}

// Whether triangle t shares a vertex with one of vertex vi's own triangles:
// then it is vi's own surface, not another layer.
SOAK_INLINE bool touchesOneRing(const ClothView& c, int vi, const ClothTriangle& t) {
  for (int k = c.vertexTriangleStart[vi]; k < c.vertexTriangleStart[vi + 1]; ++k) {
    const ClothTriangle r = c.triangles[c.vertexTriangles[k]];
    for (int a = 0; a < 3; ++a)
      if (r.v[a] == t.v[0] || r.v[a] == t.v[1] || r.v[a] == t.v[2]) return true;
  }
  return false;
}

struct ClothContactView {
  PairListView lists;      // items: the cloth particles in slot order (ClothSlots)
  PairListView triangles;  // per item: places in c.firstVertexTriangles, its own surface left out
  GridView grid;           // the cloth's grid: for items without a list
  const int* slot = nullptr;
  ClothContactStep step;
  ClothView cloth;
};

// Calls f(j) for the contact candidates of item v (its particle slot i),
// with `lanes`: this lane's share.
template <class F>
SOAK_INLINE void forEachContactCandidate(const ClothContactView& n, int v, int i, const Lanes& lanes, F&& f) {
  if (!n.lists.listed(v)) {
    forEachCandidate(n.grid, n.grid.slotKey[i], lanes, [&](int j) {
      if (mayTouchThisStep(n.step, n.cloth, i, j)) f(j);
    });
    return;
  }
  const int s = n.lists.start[v], e = s + n.lists.count[v];
  for (int k = s + lanes.index; k < e; k += lanes.size) f(n.lists.index[k]);
}

// Calls f(k, j) for the triangles that can matter to item v (its particle
// slot i) moving from x0 to x (TriangleCoupling.h's forEachTriangleNearPath
// over the candidates instead of the grid): k is the triangle's place in
// c.firstVertexTriangles, j the slot of its first vertex.
template <class F>
SOAK_INLINE void forEachCandidateTriangleNearPath(const ClothContactView& n, const ParticleView& p, int v, int i,
                                                   Vec3 x0, Vec3 x, const Lanes& lanes, F&& f) {
  const ClothView& c = n.cloth;
  const float reach = triangleReach(c.maxEdgeLength, 0.5f * c.maxThickness);
  const Vec3 path = x - x0;
  const float len2 = lengthSquared(path);
  forEachContactCandidate(n, v, i, lanes, [&](int j) {
    if (withinReachOfPath(p.predicted[j].xyz(), x0, path, len2, reach)) forEachTriangleFirstAt(c, p, j, f);
  });
}

// Calls f(k) for the triangles of other layers that can matter to item v
// (its particle slot i) moving from x0 to x: those of
// forEachCandidateTriangleNearPath, less the particle's own surface. With a
// triangle list, its first vertex's place is the snapshot's (taken from the
// same predicted positions before the pass).
template <class F>
SOAK_INLINE void forEachOtherLayerTriangleNearPath(const ClothContactView& n, const ParticleView& p, int v, int i,
                                                    Vec3 x0, Vec3 x, const Lanes& lanes, F&& f) {
  const ClothView& c = n.cloth;
  if (n.triangles.listed(v)) {
    const float reach = triangleReach(c.maxEdgeLength, 0.5f * c.maxThickness);
    const Vec3 path = x - x0;
    const float len2 = lengthSquared(path);
    const int s = n.triangles.start[v], e = s + n.triangles.count[v];
    for (int m = s + lanes.index; m < e; m += lanes.size) {
      const int k = n.triangles.index[m];
      if (withinReachOfPath(c.triangleSnapshot[k].a(), x0, path, len2, reach)) f(k);
    }
    return;
  }
  const int vi = p.id[i];
  forEachCandidateTriangleNearPath(n, p, v, i, x0, x, lanes, [&](int k, int j) {
    if (p.phase[j] != p.phase[i] || !touchesOneRing(c, vi, c.firstVertexTriangles[k])) f(k);
  });
}

class ClothContactLists {
 public:
  explicit ClothContactLists(Device d) : lists_(d), triangles_(d), device_(d) {}
  // From the particles at the step's start (`p`: positions, velocities;
  // valid from the neighbours stage, whose cloth grid `g` it walks).
  // With `sizeExactly` (a maintenance step) the buffer is sized for all lists.
  void build(ParticleView p, GridView g, ClothView c, float dt, bool sizeExactly);
  ClothContactView view() const { return view_; }
  int itemsWithoutList() const { return lists_.itemsWithoutList(); }
  int itemsWithoutTriangleList() const { return triangles_.itemsWithoutList(); }
  void setSizing(const PairListSizing& s) {  // tests: no lists at all
    lists_.setSizing(s);
    triangles_.setSizing(s);
  }
  std::vector<std::vector<int>> download() const { return lists_.download(); }
  std::vector<std::vector<int>> downloadTriangles() const { return triangles_.download(); }

 private:
  PairLists lists_;
  PairLists triangles_;
  ClothContactView view_;
  Device device_;
};

}  // namespace soak
