#include "AirDrag.h"

#include <cmath>

#include "Backend/ForEach.h"

namespace soak::airdrag {

void applyAirDrag(Device d, ParticleView p, float k, float dt) {
  const float factor = std::exp(-k * dt);
  forEach(d, p.count, SOAK_LAMBDA(int i) {
    if (p.position[i].w != 0.f) p.velocity[i] *= factor;
  }, "airdrag");
}

}  // namespace soak::airdrag
