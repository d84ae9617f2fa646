#pragma once
// Cloth-cloth and cloth self-collision: cloth particles closer than the
// cloth thickness are pushed apart, except pairs that are that close in the
// rest shape (mesh neighbours of the same cloth).
#include "Cloth/ClothSystem.h"
#include "Neighbours/GridView.h"

namespace soak {

// `passes` Jacobi passes; `delta` is scratch of particle count.
void resolveClothContacts(Device d, ParticleView p, GridView g, ClothView c, Vec3* delta, int passes);

}  // namespace soak
