#pragma once
// Volume of a cloth particle, V_i = 1 / sum_k W(x_i - x_k, h_ik) over the
// particles k of the same cloth (itself included) at the predicted positions
// (Akinci et al. 2012; the paper's Eq. 10 uses the same V_i). Written for
// the cloth particles only; other particles' entries are left as they are.
// `g` is any grid that holds the cloth particles (the cloth's own is fastest).
#include "Cloth/ClothNeighbours.h"
#include "Cloth/ForEachClothParticle.h"
#include "Neighbours/GridView.h"
#include "Particles/ParticleState.h"

#include "Fluid/SphKernels.h"

namespace soak {

// V_i for cloth particle i (item v of the cloth's slots), summed by the
// group `lanes` over the candidates `walk(i, v, lanes, f)` gives (every
// lane gets the same bits). It reads the particles' phase, radius and
// predicted x, y, z only: a pass may change their masses and .w meanwhile.
template <class Walk>
SOAK_INLINE float clothVolumeOf(const ParticleView& p, int i, int v, const Lanes& lanes, const Walk& walk) {
  const int phase = p.phase[i];
  const Vec3 xi = p.predicted[i].xyz();
  const float hi = p.radius[i];
  float sum = 0.f;
  walk(i, v, lanes, [&](int j) {
    if (p.phase[j] != phase) return;
    sum += poly6(lengthSquared(xi - p.predicted[j].xyz()), pairSupport(hi, p.radius[j]));
  });
  sum = laneSum(lanes, sum);
  return sum > 0.f ? 1.f / sum : 0.f;
}

// The cloth's lists as a walk for clothVolumeOf.
struct ClothListWalk {
  ClothNeighbourView n;
  template <class F>
  SOAK_INLINE void operator()(int, int v, const Lanes& lanes, F&& f) const {
    forEachClothNeighbour(n, v, lanes, f);
  }
};

void computeClothVolumes(Device d, ParticleView p, GridView g, ClothSlots cloth, float* volume);

}  // namespace soak
