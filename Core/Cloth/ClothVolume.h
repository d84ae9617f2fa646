#pragma once
// Volume of a cloth particle, V_i = 1 / sum_k W(x_i - x_k, h_ik) over the
// particles k of the same cloth (itself included) at the predicted positions
// (Akinci et al. 2012; the paper's Eq. 10 uses the same V_i). Written for
// the cloth particles only; other particles' entries are left as they are.
// `g` is any grid that holds the cloth particles (the cloth's own is fastest).
#include "Cloth/ClothNeighbours.h"
#include "Cloth/ForEachClothParticle.h"
#include "Neighbours/GridView.h"
#include "Particles/ParticleState.h"

namespace soak {

void computeClothVolumes(Device d, ParticleView p, GridView g, ClothSlots cloth, float* volume);
// The same over this step's cloth-cloth lists (the same bits with one lane).
void computeClothVolumes(Device d, ParticleView p, const ClothNeighbourView& n, ClothSlots cloth, float* volume);

}  // namespace soak
