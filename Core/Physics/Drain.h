#pragma once
// Where water leaves the run: outside the domain box, inside a sink box, or
// wholly absorbed by cloth (its mass is held there). Stateless, over
// particle arrays.
#include "Backend/Device.h"
#include "Particles/ParticleState.h"

namespace soak {

struct DrainRegion {
  Vec3 domainMin, domainMax;             // water outside this box drains
  const Vec3* sinkCorners = nullptr;     // device: (min, max) of each sink box
  int sinkCount = 0;
};

// Marks the water that drains as removed (kPhaseRemoved, inert, its mass
// kept for the count at compaction); nothing else: the host learns of it at
// the next compaction, so the step never waits. A non-finite position is an
// instability, not water that left: it stays for the check to report.
void markDrainedWater(Device d, ParticleView p, const DrainRegion& region);

}  // namespace soak
