#include "Drying.h"

#include "Backend/ForEach.h"
#include "WetKernels.h"

namespace soak::wet {

void evaporateWater(Device d, ParticleView p, WetArrays a, const float* vertexArea, float* evaporated,
                    const DryingParams& dry, float c, float dt) {
  const float flux = dry.fluxIntoDryAir * (1.f - dry.ambientHumidity);
  const float sC = dry.criticalSaturation;
  forEachClothParticle(d, a.cloth, SOAK_LAMBDA(int i) {
    const float held = a.held[i], V = a.volume[i];
    const float k = flux * vertexArea[p.id[i]];
    const float after = heldAfterDrying(held, k, sC * V / c, dt);
    if (after == held) return;
    a.held[i] = after;
    evaporated[i] += held - after;
    a.saturation[i] = saturationOf(c, after, V);
  }, "wet.dry");
}

}  // namespace soak::wet
