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
}  // namespace

void FluidNeighbours::build(ParticleView p, GridView g, float skin, bool sizeExactly) {
  buildPairLists(device_, lists_, p.count, sizeExactly, FluidCandidates{p, g, 1.f + skin}, 1,
                 "fluid.neighbours.count",
                 "fluid.neighbours.fill");
  const PairListView l = lists_.view();
  view_ = {l.start, l.count, l.index, l.capacity, p.phase, p.predicted, g};
}

}  // namespace soak
