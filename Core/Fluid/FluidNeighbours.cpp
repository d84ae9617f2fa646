#include "Fluid/FluidNeighbours.h"

#include "Fluid/SphKernels.h"
#include "Neighbours/PairListsBuild.h"

namespace soak {

namespace {
// The pairs the fluid passes can use (see FluidNeighbours.h), within
// `reach` times h_ij, in the grid's order.
struct FluidCandidates {
  ParticleView p;
  GridView g;
  float reach;
  template <class F>
  SOAK_INLINE void operator()(int i, const Lanes& lanes, F&& f) const {
    const int phi = p.phase[i];
    const Float4 xi4 = p.predicted[i];
    const bool moving = xi4.w > 0.f;
    if (!isWater(phi) && !(isCloth(phi) && moving)) return;
    const Vec3 xi = xi4.xyz();
    const float hi = p.radius[i];
    forEachCandidateInRounds(g, g.slotKey[i], lanes, [&](bool valid, int j) {
      bool keep = valid && fluidPairKind(phi, moving, p.phase[j]);
      if (keep) {
        const float h = pairSupport(hi, p.radius[j]) * reach;
        keep = lengthSquared(xi - p.predicted[j].xyz()) < h * h;
      }
      f(keep, j);
    });
  }
};
// A slot is its own key.
struct SlotKey {
  SOAK_INLINE int operator()(int i) const { return i; }
};
}  // namespace

void FluidNeighbours::build(ParticleView p, GridView g, float skin, bool sizeExactly) {
  const FluidCandidates candidates{p, g, 1.f + skin};
  if (lanesFor(p.count, 1) > 1) {
    // Slot i's list in room [i K, i K + K), K the mean count of the lists at
    // the last sizing plus a quarter (PairLists.h, rooms): between
    // maintenance steps one pass fills them, without counting first, and
    // keeps the lists in the grid's order; a list longer than K, or of a
    // slot past the rooms (water added since), goes to the spill. Only
    // where the lists are built by lane groups (under about a million
    // particles): built by one thread a particle, at 1M and 4M, the rooms
    // made fluid.solve 3 % slower (Doc/performance.md).
    const int keys = sizeExactly || lists_.roomKeys() == 0 ? p.count : lists_.roomKeys();
    buildKeyedPairLists(device_, lists_, p.count, sizeExactly, candidates, SlotKey{}, keys, 1,
                        "fluid.neighbours.count", "fluid.neighbours.fill", true);
  } else {
    buildPairLists(device_, lists_, p.count, sizeExactly, candidates, 1, "fluid.neighbours.count",
                   "fluid.neighbours.fill");
  }
  const PairListView l = lists_.view();
  view_ = {l.start, l.count, l.index, l.capacity, p.phase, p.predicted, g};
}

}  // namespace soak
