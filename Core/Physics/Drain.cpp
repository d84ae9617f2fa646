#include "Physics/Drain.h"

#include "Backend/ForEach.h"
#include "Particles/Phase.h"

namespace soak {

void markDrainedWater(Device d, ParticleView p, const DrainRegion& region) {
  if (p.count == 0) return;
  const Vec3 lo = region.domainMin, hi = region.domainMax;
  const Vec3* sinkBox = region.sinkCorners;
  const int sinkCount = region.sinkCount;
  forEach(d, p.count, SOAK_LAMBDA(int i) {
    if (!isWater(p.phase[i])) return;
    bool out = !(p.mass[i] > 0.f);  // wholly absorbed by cloth (its mass is held there now)
    const Vec3 x = p.position[i].xyz();
    if (!out && !isFinite(x)) return;
    if (!out) out = !(x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z);
    for (int k = 0; k < sinkCount && !out; ++k) {
      const Vec3 a = sinkBox[2 * k], b = sinkBox[2 * k + 1];
      out = x.x >= a.x && x.y >= a.y && x.z >= a.z && x.x <= b.x && x.y <= b.y && x.z <= b.z;
    }
    if (!out) return;
    // Inert from here on; a drained slot keeps its mass (counted at compaction).
    p.phase[i] = kPhaseRemoved;
    if (!(p.mass[i] > 0.f)) p.mass[i] = 0.f;
    p.position[i] = Float4(x, 0.f);
    p.predicted[i] = Float4(x, 0.f);
    p.velocity[i] = Vec3(0.f, 0.f, 0.f);
  }, "drain.mark");
}

}  // namespace soak
