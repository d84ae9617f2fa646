#include "SteadyWind.h"

#include <cmath>

#include "Backend/ForEach.h"

namespace steadywind {

void relaxTowardWind(soak::Device d, soak::ParticleView p, soak::Vec3 wind, float k, float dt) {
  const float keep = std::exp(-k * dt);
  soak::forEach(d, p.count, SOAK_LAMBDA(int i) {
    if (p.position[i].w != 0.f) p.velocity[i] = wind + (p.velocity[i] - wind) * keep;  // w = 0: pinned
  }, "wind.relax");
}

}  // namespace steadywind
