#pragma once
// Cloth sub-steps from the cloth's speed (Simulation.clothSubstepTravel).
//
// The cloth's contact tests see a pair only where its two sides meet within
// a sub-step's motion: particle contact pushes apart pairs closer than the
// thickness, and the vertex-triangle test takes the side a vertex is on at
// the sub-step's start as its own (Eq. 21). A vertex that travels more than
// its thickness in one sub-step can pass a layer between two tests, and a
// sheet that has passed through itself stays tangled (Doc/design.md, "The
// sheet tangles"). Short sub-steps keep the travel small, but a sub-step
// costs its contact passes whatever the cloth does, and most of a run the
// cloth is slow. So each step takes the fewest sub-steps that keep every
// cloth vertex within `travel` of its thickness per sub-step, estimated
// from its velocity after the predict stage (the step's start plus what
// gravity and the plugins' forces add over the step).
// Each sub-step runs clothIterations: sharing a slow step's iterations out
// over a fast step's sub-steps left the sheets stretched (Doc/design.md).
// The predict stage queues the measurement and its copy to the host, and
// the cloth stage reads it, so the host waits for the device only as far
// as predict while the device works through the stages in between.
#include "Cloth/ClothSystem.h"

namespace soak {

// Writes to *maxTravel (device memory) the largest |v| dt / thickness over
// the cloth's vertices, v the velocity the predict stage left: how many
// thicknesses the fastest vertex travels in the step. Queued without a
// wait; `scratch` holds one float per vertex.
void measureClothTravel(Device d, ParticleView p, ClothView c, float dt, float* scratch, float* maxTravel);

// Sub-steps for a travel of `perStep` thicknesses a step: ceil(perStep /
// travel) within [fewest, max(fewest, most)], the upper bound when perStep
// is not finite.
int substepsForTravel(float perStep, float travel, int fewest, int most);

}  // namespace soak
