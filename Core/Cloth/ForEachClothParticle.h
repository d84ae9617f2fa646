#pragma once
// forEachClothParticle(device, cloth, f): calls f(i) for the particle slot i
// of every cloth vertex, and for no other particle.
//
// Particles are sorted by grid cell every step, so cloth and water share
// warps; a pass over all particles that returns early for water leaves most
// lanes of a warp idle while its cloth lanes walk their neighbours (at the
// 1M scale scene three quarters of the particles are water). Walking the
// vertices instead fills every lane with cloth, in mesh order, which is also
// close to space order. The slots are valid from the neighbours stage (which
// sorts the particles and updates them) to the end of the step.
#include "Backend/ForEach.h"
#include "Cloth/ClothSystem.h"

namespace soak {

struct ClothSlots {
  const int* slot = nullptr;  // per vertex: its particle slot
  int count = 0;              // vertices
};

inline ClothSlots clothSlots(const ClothView& c) { return {c.vertexSlot, c.vertexCount}; }

template <class F>
void forEachClothParticle(Device d, ClothSlots cloth, F f, const char* what = "forEachClothParticle") {
  const int* slot = cloth.slot;
  forEach(d, cloth.count, SOAK_LAMBDA(int v) { f(slot[v]); }, what);
}

}  // namespace soak
