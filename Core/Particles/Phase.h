#pragma once
#include "Base/HostDevice.h"

namespace soak {

// Particle phase: which kind of matter a particle is. Cloth objects are
// numbered from 1 so that "same cloth" is a comparison of phases.
constexpr int kPhaseWater = 0;
constexpr int kPhaseStatic = -1;
// A slot whose particle is gone (drained, wholly absorbed) or a drip slot
// left unused: inert (inverse mass 0, neither water nor cloth) until the
// next compaction removes it (Simulation::compact, Doc/design.md). A drained
// slot keeps the water's mass so that compaction can count it as drained.
constexpr int kPhaseRemoved = -2;
SOAK_INLINE bool isRemoved(int phase) { return phase == kPhaseRemoved; }
SOAK_INLINE bool isWater(int phase) { return phase == kPhaseWater; }
SOAK_INLINE bool isCloth(int phase) { return phase > 0; }
SOAK_INLINE int clothPhase(int clothIndex) { return clothIndex + 1; }

}  // namespace soak
