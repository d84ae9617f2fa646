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

// Sub-steps from the strain the solve leaves (Simulation.clothStrainTarget).
//
// A solve of fixed iterations leaves strain that grows with the square of
// the sub-step (Tests/Unit/ClothSubstepTest.cpp), and how much depends on
// the cloth: a sheet hung from one diagonal needs about half again the
// sub-steps of one hung from an edge for the same strain. So each step also
// counts, at its start, the edges the step before left past the target ε
// and past ε / 4, over the edges the stats count (a sheet's warp and weft,
// a mesh's every edge). More than 1 % past ε (the 99th percentile over it)
// raises the sub-steps asked for by half at once. Only kStrainCalmSteps
// steps in a row with under 1 % past ε / 4 lower them, by one: the strain a
// cloth settles at depends on its sub-steps, so a count lowered as soon as
// the strain allows swings back and forth, and each change shakes the cloth
// (measured: lowered at once, a hanging sheet cycles between 4 and 9
// sub-steps every 7 steps and never comes to rest). Counts are integers, so
// the choice is the same on every backend and run; it is state, saved in
// checkpoints.
constexpr int kStrainCalmSteps = 60;
// The most sub-steps the strain asks for, in multiples of the fewest: a
// sheet draped over a ball keeps 3 % past it at 32 sub-steps, and a step's
// cost grows with its sub-steps.
constexpr int kStrainSubstepsFactor = 4;

struct StrainSubsteps {
  int substeps = 0;  // the sub-steps the strain asks for (0 before the first step)
  int calmSteps = 0; // steps in a row with the 99th percentile under target / 4
};

// Writes to counts[0] the edges whose strain |l - l0| / l0 exceeds `target`
// and to counts[1] those exceeding target / 4 (device memory), without a
// wait. `flags` and `scan` hold 2 n ints.
void measureClothStrain(Device d, ParticleView p, const int* vertexSlot, const ClothEdge* edges, const float* rest,
                        int n, float target, int* flags, int* scan, int* counts);

// What the strain asks for next, from what it asked before and the counts.
StrainSubsteps substepsForStrain(StrainSubsteps current, int above, int aboveQuarter, int edges, int fewest, int most);

}  // namespace soak
