#pragma once
// Cloth sub-steps from the cloth's speed (Simulation.clothSubstepTravel).
//
// The cloth's contact tests see a pair only where its two sides meet within
// a sub-step's motion: particle contact pushes apart pairs closer than the
// thickness, and the vertex-triangle test takes the side a vertex is on at
// the sub-step's start as its own (Eq. 21). A vertex that travels more than
// its thickness in one sub-step can pass a layer between two tests, and a
// sheet that has passed through itself stays tangled (Doc/design.md,
// "Tangles and the crossing guard"). Short sub-steps keep the travel small, but a sub-step
// costs its iterations whatever the cloth does, and most of a run the
// cloth is slow. So each step takes the fewest sub-steps that keep every
// cloth vertex within `travel` of its thickness per sub-step, estimated
// from its velocity after the predict stage (the step's start plus what
// gravity and the plugins' forces add over the step).
// Each sub-step runs clothIterations: sharing a slow step's iterations out
// over a fast step's sub-steps left the sheets stretched (Doc/design.md).
// The predict stage queues the measurement and the cloth stage the choice,
// both on the device, where the sub-steps read it (SubstepClock.h): inside
// a step graph the host never learns the count (Backend/DeviceLoop.h).
#include <cmath>

#include "Base/HostDevice.h"
#include "Cloth/ClothSystem.h"

namespace soak {

// Writes to *maxTravel (device memory) the largest |v| dt / thickness over
// the cloth's vertices, v the velocity the predict stage left: how many
// thicknesses the fastest vertex travels in the step. Queued without a
// wait; `scratch` holds one float per vertex.
void measureClothTravel(Device d, ParticleView p, ClothView c, float dt, float* scratch, float* maxTravel);

// Sub-steps for a travel of `perStep` thicknesses a step: ceil(perStep /
// travel) within [fewest, max(fewest, most)], the upper bound when perStep
// is not finite. On the device as well: the step's count is chosen there
// (ClothStep.h).
SOAK_INLINE int substepsForTravel(float perStep, float travel, int fewest, int most) {
  const int top = most > fewest ? most : fewest;
  if (!(fabsf(perStep) <= 3.402823466e38f)) return top;  // inf or NaN
  const double wanted = ceil(double(perStep) / double(travel));
  return wanted < double(fewest) ? fewest : wanted > double(top) ? top : int(wanted);
}

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

// Contact passes from the speed (Simulation.clothContactsBySpeed).
//
// The travel rule above exists for the contacts: a contact pass is sound
// while no vertex travels more than `travel` of its thickness between two
// passes. Sub-steps beyond the travel's count (a scene's fewest, the
// strain's) are for the solve's convergence, which the contact passes do
// not help: a sub-step's contact passes cost about as much as its 12
// Jacobi iterations (Doc/performance.md). So with contacts from the speed a
// step of n sub-steps runs them in only as many as the travel asks for,
// spread evenly and always in the last (SubstepTime::contactsIn); between
// two such sub-steps the contact tests take the vertex's path over all the
// sub-steps since the last (ClothSubstepScratch::contactStart).
SOAK_INLINE int contactSubstepsForTravel(float perStep, float travel, int substeps) {
  return substepsForTravel(perStep, travel, 1, substeps);
}

struct SubstepClock;
// How a step's count is chosen: `fewest` (Simulation.clothSubsteps) unless
// travel > 0 (Simulation.clothSubstepTravel): then from the largest travel
// up to `most`, and from the strain counts (where measured) up to
// `strainMost`, the larger of the two.
struct SubstepChoice {
  int fewest = 1;
  float travel = 0.f;
  int most = 1;
  int strainMost = 1;
  int strainEdges = 0;
  bool contactsBySpeed = false;  // Simulation.clothContactsBySpeed
};
// Writes the step's count to the clock (its substep 0, its total taken up),
// on the device, from *maxTravel and, where not null, strainCounts[0..1]
// (measureClothTravel, measureClothStrain); the strain's state is the
// clock's.
void chooseClothSubsteps(Device d, SubstepClock* clock, const float* maxTravel, const int* strainCounts,
                         SubstepChoice choice);

// What the strain asks for next, from what it asked before and the counts.
SOAK_INLINE StrainSubsteps substepsForStrain(StrainSubsteps current, int above, int aboveQuarter, int edges, int fewest,
                                             int most) {
  const int top = fewest > most ? fewest : most;
  StrainSubsteps next = current;
  next.substeps = current.substeps < fewest ? fewest : current.substeps > top ? top : current.substeps;
  const long long onePercent = (static_cast<long long>(edges) + 99) / 100;  // edges past the 99th percentile
  if (above > onePercent) {
    const int raise = next.substeps / 2 > 1 ? next.substeps / 2 : 1;
    next.substeps = next.substeps + raise < top ? next.substeps + raise : top;
    next.calmSteps = 0;
  } else if (aboveQuarter < onePercent) {
    if (++next.calmSteps >= kStrainCalmSteps) {
      next.substeps = next.substeps - 1 > fewest ? next.substeps - 1 : fewest;
      next.calmSteps = 0;
    }
  } else {
    next.calmSteps = 0;
  }
  return next;
}

}  // namespace soak
