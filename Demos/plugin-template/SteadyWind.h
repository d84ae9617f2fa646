#pragma once
// A steady wind that free particles relax toward: dv/dt = k (w - v).
#include "Particles/ParticleState.h"

namespace steadywind {

// v <- w + (v - w) exp(-k dt): the exact solution over one step, so the
// result does not depend on the time step.
void relaxTowardWind(soak::Device d, soak::ParticleView p, soak::Vec3 wind, float k, float dt);

}  // namespace steadywind
