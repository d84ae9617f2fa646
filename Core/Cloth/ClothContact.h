#pragma once
// Cloth-cloth and cloth self-collision: cloth particles closer than the
// cloth thickness are pushed apart, except pairs that are that close in the
// rest shape (mesh neighbours of the same cloth); and vertex-triangle
// contact, which keeps a vertex from slipping through another layer.
#include "Cloth/ClothContactLists.h"
#include "Cloth/ClothSystem.h"
#include "Neighbours/GridView.h"

namespace soak {

// `passes` Jacobi passes over the step's candidate pairs `n`, on `p` (the
// step's or a cloth sub-step's positions); `scratch` holds particle count
// positions (the passes write x* and scratch in turn). With onlyIf (device
// memory), the launches do nothing unless *onlyIf is 1 when they run: a
// sub-step without contact passes (SubstepClock.h, contactsIn).
void resolveClothContacts(Device d, ParticleView p, ClothContactView n, Float4* scratch, int passes,
                          const int* onlyIf = nullptr);

// A cloth vertex that would cross a triangle of another layer (another
// cloth, or a part of its own cloth that shares no vertex with its own
// triangles) between its start-of-step and predicted positions is put back on
// the side it came from, thickness / 2 away. Particle contact alone lets a
// vertex slip between the other layer's vertices when a fold flattens.
// The triangles come from the step's candidate pairs `n`. onlyIf: as above.
void resolveVertexTriangleContacts(Device d, ParticleView p, ClothContactView n, const int* onlyIf = nullptr);

}  // namespace soak
