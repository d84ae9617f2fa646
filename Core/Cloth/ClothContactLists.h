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
// the reach plus how far the two move toward each other. The lists keep,
// for each cloth particle, the cloth particles j with
//
//     |x_i - x_j| < max(3 c_ij, t) + (1.5 |v_i - v_j| + 0.5 (|v_i| + |v_j|)) dt
//
// (x, v at the step's start) in the grid's order. The relative velocity is
// how fast the pair closes while both fly on; the speeds' share covers,
// with the margin measured below, how far the step can turn either from
// that course (a vertex stopped by a collider or by the layer below, the
// constraints). A sheet falling as a whole
// lists its neighbourhood, not everything it passes: at 1.5 m/s and
// dt = 0.015 s, 3 (|v_i| + |v_j|) dt would be 13.5 cm.
//
// Measured: on a sheet crumpling onto the floor (ClothContactListsTest),
// every pair that ended a step within 1.5 c_ij had started within 0.69 of
// this reach. The CPU output of fig7_small (30 frames), fig3b (20) and
// small fig9b (90, through its landing on the ball) has the same bits as
// with the reach max(3 c_ij, t) + 3 (|v_i| + |v_j|) dt: no contact was
// lost. Over the whole runs of fig6b, fig9a and fig9b on the H100,
// `cloth.solve` takes 11-13 % less (Doc/performance.md).
//
// An item without a list (past the buffer's capacity, PairLists.h) walks
// the grid and applies the same test to the same start positions, so it
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
constexpr float kContactReachRelative = 1.5f;  // |v_i - v_j| dt in it
constexpr float kContactReachMotion = 0.5f;    // (|v_i| + |v_j|) dt in it

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
                      (kContactReachRelative * length(s.velocity[i] - s.velocity[j]) +
                       kContactReachMotion * (length(s.velocity[i]) + length(s.velocity[j]))) *
                          s.dt;
  return lengthSquared(s.position[i].xyz() - s.position[j].xyz()) < reach * reach;
}

struct ClothContactView {
  PairListView lists;      // items: the cloth particles in slot order (ClothSlots)
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

// A vertex's path x0 -> x in the search for triangles: a cloth particle's
// triangles (those it is the first vertex of) can matter to the vertex if
// the particle lies within the triangle reach of the path (TriangleCoupling.h).
struct TrianglePath {
  Vec3 x0, path;
  float len2, reach;
  SOAK_INLINE TrianglePath(const ClothView& c, Vec3 from, Vec3 to)
      : x0(from), path(to - from), len2(lengthSquared(to - from)),
        reach(triangleReach(c.maxEdgeLength, 0.5f * c.maxThickness)) {}
  SOAK_INLINE bool near(Vec3 y) const { return withinReachOfPath(y, x0, path, len2, reach); }
  // Whether the triangles [first, last) of c.firstVertexTriangles, those of
  // one candidate, can matter: the candidate's place is read from the
  // snapshot (its first triangle's first vertex, TriangleSnapshot::a), so
  // the pass reads no x* but its own vertex's.
  SOAK_INLINE bool nearTriangles(const ClothView& c, int first, int last) const {
    return first < last && near(c.triangleSnapshot[first].a());
  }
};

// Calls f(k, j) for the triangles that can matter to item v (its particle
// slot i) moving from x0 to x (TriangleCoupling.h's forEachTriangleNearPath
// over the candidates instead of the grid): k is the triangle's place in
// c.firstVertexTriangles, j the slot of its first vertex.
template <class F>
SOAK_INLINE void forEachCandidateTriangleNearPath(const ClothContactView& n, const ParticleView& p, int v, int i,
                                                   Vec3 x0, Vec3 x, const Lanes& lanes, F&& f) {
  const TrianglePath path(n.cloth, x0, x);
  const ClothView& c = n.cloth;
  forEachContactCandidate(n, v, i, lanes, [&](int j) {
    const int vj = p.id[j];
    if (path.nearTriangles(c, c.firstVertexTriangleStart[vj], c.firstVertexTriangleStart[vj + 1]))
      forEachTriangleFirstAt(c, p, j, f);
  });
}

class ClothContactLists {
 public:
  explicit ClothContactLists(Device d) : lists_(d), device_(d) {}
  // From the particles at the step's start (`p`: positions, velocities;
  // valid from the neighbours stage, whose cloth grid `g` it walks).
  // With `sizeExactly` (a maintenance step) the buffer is sized for all lists.
  void build(ParticleView p, GridView g, ClothView c, float dt, bool sizeExactly);
  ClothContactView view() const { return view_; }
  int itemsWithoutList() const { return lists_.itemsWithoutList(); }
  void setSizing(const PairListSizing& s) { lists_.setSizing(s); }  // tests: no lists at all
  std::vector<std::vector<int>> download() const { return lists_.download(); }

 private:
  PairLists lists_;
  ClothContactView view_;
  Device device_;
};

}  // namespace soak
