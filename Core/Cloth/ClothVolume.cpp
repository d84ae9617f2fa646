#include "Cloth/ClothVolume.h"

#include "Backend/ForEach.h"
#include "Fluid/SphKernels.h"

namespace soak {

namespace {
struct GridWalk {
  GridView g;
  template <class F>
  SOAK_INLINE void operator()(int i, int, const Lanes& lanes, F&& f) const {
    forEachCandidate(g, g.slotKey[i], lanes, f);
  }
};
struct ListWalk {
  ClothNeighbourView n;
  template <class F>
  SOAK_INLINE void operator()(int, int v, const Lanes& lanes, F&& f) const {
    forEachClothNeighbour(n, v, lanes, f);
  }
};

template <class Walk>
void volumes(Device d, ParticleView p, Walk walk, ClothSlots cloth, float* volume, int minLanes) {
  forEachClothItemLanes(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const int phase = p.phase[i];
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i];
    float sum = 0.f;
    walk(i, v, lanes, [&](int j) {
      if (p.phase[j] != phase) return;
      sum += poly6(lengthSquared(xi - p.predicted[j].xyz()), pairSupport(hi, p.radius[j]));
    });
    sum = laneSum(lanes, sum);
    if (lanes.leader()) volume[i] = sum > 0.f ? 1.f / sum : 0.f;
  }, "cloth.volume", minLanes);
}
}  // namespace

void computeClothVolumes(Device d, ParticleView p, GridView g, ClothSlots cloth, float* volume) {
  volumes(d, p, GridWalk{g}, cloth, volume, 1);
}

void computeClothVolumes(Device d, ParticleView p, const ClothNeighbourView& n, ClothSlots cloth, float* volume) {
  volumes(d, p, ListWalk{n}, cloth, volume, kListLanes);
}

}  // namespace soak
