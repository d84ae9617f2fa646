#include "Cloth/ClothVolume.h"

#include "Backend/ForEach.h"

namespace soak {

namespace {
struct GridWalk {
  GridView g;
  template <class F>
  SOAK_INLINE void operator()(int i, int, const Lanes& lanes, F&& f) const {
    forEachCandidate(g, g.slotKey[i], lanes, f);
  }
};

template <class Walk>
void volumes(Device d, ParticleView p, Walk walk, ClothSlots cloth, float* volume, int minLanes) {
  forEachClothItemLanes(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const float V = clothVolumeOf(p, i, v, lanes, walk);
    if (lanes.leader()) volume[i] = V;
  }, "cloth.volume", minLanes);
}
}  // namespace

void computeClothVolumes(Device d, ParticleView p, GridView g, ClothSlots cloth, float* volume) {
  volumes(d, p, GridWalk{g}, cloth, volume, 1);
}

void computeClothVolumes(Device d, ParticleView p, const ClothNeighbourView& n, ClothSlots cloth, float* volume) {
  volumes(d, p, ClothListWalk{n}, cloth, volume, kListLanes);
}

}  // namespace soak
