#pragma once
// wet.dry: evaporation from the water the fabric holds (beyond the paper;
// Doc/model.md, "Drying").
//
// The classical two periods of drying a porous sheet (e.g. Mujumdar,
// "Handbook of Industrial Drying", ch. 1): while the fabric is wetter than
// a critical saturation S_c, water reaches the surface as fast as it leaves
// and the flux per area is fixed by the air, E = E_0 (1 - RH) (E_0 the flux
// into dry air, RH the ambient relative humidity: the vapour-pressure
// deficit scales with 1 - RH); below S_c the flux falls with the water
// left, E = E_0 (1 - RH) S / S_c. For one cloth particle of area A and
// volume V (Eq. 10: held = S V / c) this is
//   d held / dt = -k              while held >= H_c = S_c V / c,
//   d held / dt = -k held / H_c   below,                k = E_0 (1 - RH) A,
// which evaporateWater integrates exactly over a step, so the result does
// not depend on the time step.
#include "Base/HostDevice.h"
#include "WetPhysics.h"

namespace soak::wet {

struct DryingParams {
  float fluxIntoDryAir = 0.f;       // E_0, kg / (m^2 s); 0: no drying
  float ambientHumidity = 0.5f;     // RH, [0, 1]
  float criticalSaturation = 0.1f;  // S_c
};

// Held water left after `dt` of drying from `held`, with k and H_c as above
// (exact solution of the two-period equation).
SOAK_INLINE float heldAfterDrying(float held, float k, float heldCritical, float dt) {
  if (!(k > 0.f) || !(held > 0.f)) return held;
  if (!(heldCritical > 0.f)) return fmaxf(held - k * dt, 0.f);
  float t = dt;
  if (held > heldCritical) {
    const float constantPeriod = (held - heldCritical) / k;
    if (t <= constantPeriod) return held - k * t;
    t -= constantPeriod;
    held = heldCritical;
  }
  return held * expf(-k / heldCritical * t);
}

// wet.dry: every cloth particle's held water dries for dt; what leaves is
// added to `evaporated` (per slot, kg) and the saturation follows (Eq. 10).
// `vertexArea` is each vertex's rest area (ClothSystem::vertexRestAreas).
void evaporateWater(Device d, ParticleView p, WetArrays a, const float* vertexArea, float* evaporated,
                    const DryingParams& dry, float c, float dt);

}  // namespace soak::wet
