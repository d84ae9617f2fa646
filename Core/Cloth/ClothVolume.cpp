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
}  // namespace

void computeClothVolumes(Device d, ParticleView p, GridView g, ClothSlots cloth, float* volume) {
  const GridWalk walk{g};
  forEachClothItemLanes(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const float V = clothVolumeOf(p, i, v, lanes, walk);
    if (lanes.leader()) volume[i] = V;
  }, "cloth.volume");
}

}  // namespace soak
