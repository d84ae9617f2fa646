// wet.dry (after wet.stick, where dryingRate > 0): evaporation from the
// water the fabric holds (Drying.h).
#include "Drying.h"

#include "Backend/ForEach.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "WetKernels.h"
#include "WetState.h"

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

void runDry(WetState& st, Simulation& s) {
  evaporateWater(s.device(), s.particles.view(), st.arrays(s), st.vertexArea.data(), s.particles.channel(st.evaporated),
                 st.drying, st.w.c, float(s.settings.timeStep));
}

}  // namespace soak::wet
