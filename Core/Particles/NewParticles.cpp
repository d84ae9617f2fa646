#include "Particles/NewParticles.h"

#include "Backend/ForEach.h"

namespace soak {

void writeWaterLayer(Device d, ParticleView p, int first, const Vec3* offsets, int k, const WaterLayer& layer) {
  const WaterLayer l = layer;
  forEach(d, k, SOAK_LAMBDA(int j) {
    const int i = first + j;
    const Float4 x(l.origin + offsets[j] + l.direction * l.along, 1.f / l.mass);
    p.position[i] = x;
    p.predicted[i] = x;
    p.velocity[i] = l.velocity;
    p.mass[i] = l.mass;
    p.radius[i] = l.radius;
    p.phase[i] = kPhaseWater;
    p.id[i] = l.firstId + j;
  }, "emit.layer");
}

}  // namespace soak
