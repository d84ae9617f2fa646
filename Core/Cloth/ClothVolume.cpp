#include "Cloth/ClothVolume.h"

#include "Backend/ForEach.h"
#include "Fluid/SphKernels.h"

namespace soak {

void computeClothVolumes(Device d, ParticleView p, GridView g, ClothSlots cloth, float* volume) {
  forEachClothParticleLanes(d, cloth, SOAK_LAMBDA(int i, Lanes lanes) {
    const int phase = p.phase[i];
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i];
    float sum = 0.f;
    forEachCandidate(g, g.slotKey[i], lanes, [&](int j) {
      if (p.phase[j] != phase) return;
      sum += poly6(lengthSquared(xi - p.predicted[j].xyz()), pairSupport(hi, p.radius[j]));
    });
    sum = laneSum(lanes, sum);
    if (lanes.leader()) volume[i] = sum > 0.f ? 1.f / sum : 0.f;
  }, "cloth.volume");
}

}  // namespace soak
