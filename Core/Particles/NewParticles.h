#pragma once
// Particles written straight into appended slots on the device
// (ParticleState::appendSlots), so that an emitter sends nothing from the
// host inside a step (Simulation.h, "counts stay on the device").
#include "Backend/Device.h"
#include "Base/Vec3.h"
#include "Particles/ParticleState.h"

namespace soak {

// One layer of a jet: slot first + j holds a water particle at
// origin + offsets[j] + direction * along, moving at velocity, with serial
// number firstId + j, for j in [0, k).
struct WaterLayer {
  Vec3 origin, direction, velocity;
  float along = 0.f, mass = 0.f, radius = 0.f;
  int firstId = 0;
};
void writeWaterLayer(Device d, ParticleView p, int first, const Vec3* offsets, int k, const WaterLayer& layer);

}  // namespace soak
