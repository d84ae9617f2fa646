#include "Cloth/AdaptiveSubsteps.h"

#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"

namespace soak {

void measureClothTravel(Device d, ParticleView p, ClothView c, float dt, float* scratch, float* maxTravel) {
  forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
    const int slot = c.vertexSlot[v];
    scratch[v] = length(p.velocity[slot]) * dt / c.thickness[v];
  }, "cloth.substeps.travel");
  reduceMaxInto(d, scratch, c.vertexCount, maxTravel);
}

int substepsForTravel(float perStep, float travel, int fewest, int most) {
  if (!std::isfinite(perStep)) return std::max(fewest, most);
  const double wanted = std::ceil(double(perStep) / double(travel));
  return int(std::clamp(wanted, double(fewest), double(std::max(fewest, most))));
}

}  // namespace soak
