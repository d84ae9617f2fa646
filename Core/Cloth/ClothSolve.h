#pragma once
// The cloth stages of the step (stateless over particle and cloth arrays).
#include <vector>

#include "Cloth/ClothSystem.h"
#include "Physics/Collider.h"

namespace soak {

// Pinned vertices attached to a collider follow it: x* = rest + displacement.
void moveAttachedVertices(Device d, ParticleView p, ClothView c, const Collider* colliders);

// `iterations` rounds of stretch (Eq. 8) and bend (Eq. 9) projections, one
// colour at a time (Gauss-Seidel between colours, parallel within one).
void solveClothConstraints(Device d, ParticleView p, ClothView c, const std::vector<int>& stretchColours,
                           const std::vector<int>& bendColours, int iterations, float dt);

}  // namespace soak
