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

}  // namespace

void ClothContactLists::build(ParticleView p, GridView g, ClothView c, float dt, bool sizeExactly) {
  const ClothSlots cloth = clothSlots(c);
  const ClothContactStep step{p.position, p.velocity, p.phase, p.id, dt};
  buildKeyedPairLists(device_, lists_, cloth.count, sizeExactly, ContactCandidates{g, cloth.slot, step, c},
                      ClothVertexOfItem{p.id, cloth.slot}, cloth.count, kListLanes, "cloth.contact.lists.count",
                      "cloth.contact.lists.fill");
  view_ = {lists_.view(), g, cloth.slot, step, c};
}

}  // namespace soak
