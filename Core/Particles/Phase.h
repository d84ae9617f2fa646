#pragma once
#include "Base/HostDevice.h"

namespace soak {

// Particle phase: which kind of matter a particle is. Cloth objects are
// numbered from 1 so that "same cloth" is a comparison of phases.
constexpr int kPhaseWater = 0;
constexpr int kPhaseStatic = -1;
SOAK_INLINE bool isWater(int phase) { return phase == kPhaseWater; }
SOAK_INLINE bool isCloth(int phase) { return phase > 0; }
SOAK_INLINE int clothPhase(int clothIndex) { return clothIndex + 1; }

}  // namespace soak
