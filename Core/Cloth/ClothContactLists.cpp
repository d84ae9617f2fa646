#include "Cloth/ClothContactLists.h"

#include "Neighbours/PairListsBuild.h"

namespace soak {

namespace {
struct ContactCandidates {
  GridView g;
  const int* slot;
  ClothContactStep step;
  ClothView c;
  template <class F>
  SOAK_INLINE void operator()(int v, const Lanes& lanes, F&& f) const {
    const int i = slot[v];
    forEachCandidateInRounds(g, g.slotKey[i], lanes,
                             [&](bool valid, int j) { f(valid && mayTouchThisStep(step, c, i, j), j); });
  }
};

// The triangles of item v's candidates, in their order, kept unless they
// are the particle's own surface. One thread an item: the walk over each
// candidate's triangles is not in rounds.
struct OtherLayerTriangles {
  ClothContactView n;
  template <class F>
  SOAK_INLINE void operator()(int v, const Lanes&, F&& f) const {
    const ClothView& c = n.cloth;
    const int i = n.slot[v], vi = n.step.id[i];
    forEachContactCandidate(n, v, i, Lanes{}, [&](int j) {
      const bool sameCloth = n.step.phase[j] == n.step.phase[i];
      const int vj = n.step.id[j];
      for (int k = c.firstVertexTriangleStart[vj]; k < c.firstVertexTriangleStart[vj + 1]; ++k)
        f(!sameCloth || !touchesOneRing(c, vi, c.firstVertexTriangles[k]), k);
    });
  }
};

}  // namespace

void ClothContactLists::build(ParticleView p, GridView g, ClothView c, float dt, bool sizeExactly) {
  const ClothSlots cloth = clothSlots(c);
  const ClothContactStep step{p.position, p.velocity, p.phase, p.id, dt};
  buildKeyedPairLists(device_, lists_, cloth.count, sizeExactly, ContactCandidates{g, cloth.slot, step, c},
                      ClothVertexOfItem{p.id, cloth.slot}, cloth.count, kListLanes, "cloth.contact.lists.count",
                      "cloth.contact.lists.fill");
  view_ = {lists_.view(), PairListView{}, g, cloth.slot, step, c};
  if (c.triangleCount == 0) return;
  buildKeyedPairLists(device_, triangles_, cloth.count, sizeExactly, OtherLayerTriangles{view_},
                      ClothVertexOfItem{p.id, cloth.slot}, cloth.count, 0, "cloth.triangle.lists.count",
                      "cloth.triangle.lists.fill");
  view_.triangles = triangles_.view();
}

}  // namespace soak
