#include "Cloth/ClothNeighbours.h"

#include "Fluid/SphKernels.h"
#include "Neighbours/PairListsBuild.h"

namespace soak {

namespace {
// Cloth particles within max(h_ij, th_i + th_j) of item v's, in the cloth
// grid's order. The reach is grown by 1e-4 so that no pair a pass accepts
// (with its own r^2 < h^2 at the same positions) can be left out by rounding.
struct ClothCandidates {
  ParticleView p;
  GridView g;
  const int* slot;
  const float* thickness;
  template <class F>
  SOAK_INLINE void operator()(int v, const Lanes& lanes, F&& f) const {
    const int i = slot[v];
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i], thi = thickness[p.id[i]];
    forEachCandidateInRounds(g, g.slotKey[i], lanes, [&](bool valid, int j) {
      bool keep = valid;
      if (keep) {
        const float reach = 1.0001f * maxf(pairSupport(hi, p.radius[j]), thi + thickness[p.id[j]]);
        keep = lengthSquared(xi - p.predicted[j].xyz()) < reach * reach;
      }
      f(keep, j);
    });
  }
};

}  // namespace

void ClothNeighbours::build(ParticleView p, GridView g, ClothSlots cloth, const float* thickness, bool sizeExactly,
                            bool lanes) {
  // Keyed by vertex: between maintenance steps one pass fills each list
  // into its vertex's room (PairLists.h).
  buildKeyedPairLists(device_, lists_, cloth.count, sizeExactly, ClothCandidates{p, g, cloth.slot, thickness},
                      ClothVertexOfItem{p.id, cloth.slot}, cloth.count, lanes ? kListLanes : 0, "cloth.neighbours.count",
                      "cloth.neighbours.fill");
  view_ = {lists_.view(), g, cloth.slot};
}

}  // namespace soak
