#pragma once
// <Wring cap="S"/>: wrings the fabric after WetCloth's diffusion, so that no
// cloth particle holds more than saturation `cap`; what it wrings out goes
// to the particle's emission buffer (water is conserved).
#include "Particles/ParticleState.h"

namespace soak {
class Simulation;
}

namespace wring {

struct WringState {
  float cap = 0.2f;
  int held = -1, buffer = -1, saturation = -1;  // WetCloth's channels, found at the first step
};

// The physics: per cloth particle with S > cap, held water x (1 - cap / S)
// moves to the buffer and S becomes cap (S is proportional to held water, Eq. 10).
void squeeze(soak::Device d, soak::ParticleView p, float* held, float* buffer, float* saturation, float cap);

// The stage (Stages/Squeeze.cpp).
void runSqueeze(WringState& state, soak::Simulation& sim);

}  // namespace wring
