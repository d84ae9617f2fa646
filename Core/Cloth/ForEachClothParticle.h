#pragma once
// forEachClothParticle(device, cloth, f): calls f(i) for the particle slot i
// of every cloth vertex, and for no other particle.
//
// Particles are sorted by grid cell every step, so cloth and water share
// warps; a pass over all particles that returns early for water leaves most
// lanes of a warp idle while its cloth lanes walk their neighbours (at the
// 1M scale scene three quarters of the particles are water). Walking the
// cloth's slots in increasing order instead fills every lane with cloth and
// keeps the grid's order, so neighbouring lanes query the same cells.
// (Walking the vertices in mesh order makes these passes 1.4-1.8x slower on
// the H100: a warp's lanes then lie along a row of the sheet, in different
// cells.) The slots are valid from the neighbours stage
// (which sorts the particles and updates them) to the end of the step.
#include "Backend/ForEach.h"
#include "Cloth/ClothSystem.h"

namespace soak {

struct ClothSlots {
  const int* slot = nullptr;  // the cloth particles' slots, in increasing order
  int count = 0;              // cloth particles (= vertices)
};

inline ClothSlots clothSlots(const ClothView& c) { return {c.clothSlots, c.vertexCount}; }

// A cloth item's key for keyed pair lists (Neighbours/PairLists.h): its
// particle's vertex, which no reordering changes.
struct ClothVertexOfItem {
  const int* id;
  const int* slot;
  SOAK_INLINE int operator()(int v) const { return id[slot[v]]; }
};

template <class F>
void forEachClothParticle(Device d, ClothSlots cloth, F f, const char* what = "forEachClothParticle") {
  const int* slot = cloth.slot;
  forEach(d, cloth.count, SOAK_LAMBDA(int v) { f(slot[v]); }, what);
}

// The same with f(i, lanes): a group of lanes per cloth particle on the GPU
// (Base/Lanes.h), for passes that loop over neighbours.
template <class F>
void forEachClothParticleLanes(Device d, ClothSlots cloth, F f, const char* what = "forEachClothParticleLanes") {
  const int* slot = cloth.slot;
  forEachLanes(d, cloth.count, SOAK_LAMBDA(int v, Lanes lanes) { f(slot[v], lanes); }, what);
}

// The same with f(i, v, lanes): v is the particle's place among the cloth's
// slots (the item of per-cloth-particle arrays such as ClothNeighbours').
// minLanes: kListLanes for passes over lists. minBlocksPerSm: as
// forEachLanes' (registers capped to fit that many blocks on an SM).
template <int minBlocksPerSm = 0, class F>
void forEachClothItemLanes(Device d, ClothSlots cloth, F f, const char* what = "forEachClothItemLanes",
                           int minLanes = 1) {
  const int* slot = cloth.slot;
  forEachLanes<minBlocksPerSm>(d, cloth.count, SOAK_LAMBDA(int v, Lanes lanes) { f(slot[v], v, lanes); }, what,
                               minLanes);
}

}  // namespace soak
