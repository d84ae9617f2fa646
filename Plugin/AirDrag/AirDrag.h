#pragma once
#include "Particles/ParticleState.h"

namespace soak::airdrag {

// Linear air drag on free particles: v <- v * exp(-k dt). Exact for the
// ODE dv/dt = -k v, so stable at any time step.
void applyAirDrag(Device d, ParticleView p, float k, float dt);

}  // namespace soak::airdrag
