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
// counts, at its start, the edges the step before left past the target ε,
// over the edges the stats count (a sheet's warp and weft, a mesh's every
// edge). More than 1 % past ε (the 99th percentile over it) raises the
// sub-steps asked for at once: by one, or by half where the strain is
// spread over the cloth (kStrainWidePercent below).
//
// Lowering follows the same h^2 law: strain left at m sub-steps would be
// (m / k)^2 times as large at k. Each step also counts the edges whose
// strain, so predicted at the count the rule would lower to (a quarter
// fewer, strainLoweredSubsteps), passes kStrainLoweringMargin ε. After
// kStrainCalmSteps steps in a row with under 1 % of them, the count is
// lowered. The margin keeps the lowered count's strain under the raising
// threshold, so the count does not swing back: a count that changes
// moves the shape the solve settles at, and a cloth whose count swings
// never comes to rest. The calm spell lets the strain settle at a new
// count before it is judged. Counts are integers, so the choice is the
// same on every backend and run; it is state, saved in checkpoints.
constexpr int kStrainCalmSteps = 10;
constexpr float kStrainLoweringMargin = 0.8f;
// The law is an upper bound: much of a loaded sheet's strain does not
// shrink with the sub-step (fig3a at fixed counts, 1.5 s: p99 1.90 % at 4
// sub-steps, 1.47 % at 6, 1.10 % at 9, 1.01 % at 13, about 0.9 % + 16 % /
// S^2), so by the law alone a count its first frames raised never comes
// down. After kStrainSteadySteps steps without a raise the rule therefore
// also lowers where the strain as it is (not scaled) stays under the
// margin: a probe. A probe that a raise undoes within kStrainProbeSteps
// doubles the steady spell the next one waits for (up to
// kStrainMostSteadySteps), so a cloth whose strain does follow the law is
// raised ever more rarely; one that holds resets the wait.
// A probe's margin is wider than the law's: a loaded sheet's strain at
// rest sits close to its floor, and fig7's water-laden sheet rests at
// 1.6-1.7 % p99 at 5 sub-steps and 1.7-1.8 % at 4 (CPU, 2 s), so under
// 0.8 of a 2 % target it kept 5 (6.1 sub-steps a step over the run), under
// 0.9 it comes down to 4 within 1.1 s (5.4) and stays there. A probe must
// also keep the strain the law predicts at the lowered count under
// kStrainProbeLawMargin of the target: the law overstates a loaded sheet's
// strain, but not by more than half again, and a sheet hung from one
// diagonal, whose strain does follow it, was otherwise probed from 3
// sub-steps to 2, where its wrinkles passed the target on over 3 % of its
// edges, and each undone probe shook it (kinetic energy back to 7e-4 of its
// peak after 4 s).
constexpr float kStrainProbeMargin = 0.9f;
constexpr float kStrainProbeLawMargin = 1.5f;
constexpr int kStrainSteadySteps = 20;
constexpr int kStrainMostSteadySteps = 1280;
constexpr int kStrainProbeSteps = 2 * kStrainCalmSteps;
// Raising. A raise lowers the strain the solve settles at, and the
// vertices move there within a few sub-steps: the change of count pulls
// the cloth, a snap the next measurement sees as more strain. Raised by
// half each step while past the target, fig9's soaked sheet met the ball's
// lift at 9 sub-steps and went 9, 13, 19, 32 within four steps at 3.8-5.5 %
// p99, where one sub-step more a step kept it at 2.5 % (CPU and H100,
// Doc/performance.md, "The strain rule's probes and raises"); raising by
// half only past 1.25 of the target, or at most every fifth step, still
// snapped there (4.9 % and 3.0-3.7 %). So a step with more than 1 % of its
// edges past the target raises the count by one, and by half only where
// more than kStrainWidePercent % of them are: a load spread over the cloth,
// as on the scale scenes' sheets under a falling block (4.4 % p99 at one a
// step, 3.2 % so), where a lift or a landing strains a patch.
constexpr int kStrainWidePercent = 3;
// The most sub-steps the strain asks for, in multiples of the fewest. A
// sheet pinned at its four corners under a water block (the scale scenes)
// stretches 4.0-4.1 % p99 at 16 sub-steps and 2.9-3.1 % at 32 (H100 whole
// runs, Doc/performance.md); past the cap a step's cost grows with its
// sub-steps for little.
constexpr int kStrainSubstepsFactor = 8;

struct StrainSubsteps {
  int substeps = 0;  // the sub-steps the strain asks for (0 before the first step)
  int calmSteps = 0; // steps in a row calm enough to lower them
  int leftBy = 0;    // the sub-steps of the step whose strain the next measurement sees (0 before the first step)
  int steadySteps = 0;  // steps since the last raise (at most kStrainMostSteadySteps)
  int steadyWait = kStrainSteadySteps;  // the steady steps a probe waits for
  int probeAge = -1;    // steps since the last probe lowered the count, -1: none under watch
};
// Whether the next lowering may be a probe (the strain as it is under the margin).
SOAK_INLINE bool strainProbing(StrainSubsteps s) { return s.steadySteps >= s.steadyWait; }

// The count the strain lowers to from `substeps`: a quarter fewer, one at
// least, not under the fewest.
SOAK_INLINE int strainLoweredSubsteps(int substeps, int fewest) {
  const int drop = substeps / 4 > 1 ? substeps / 4 : 1;
  return substeps - drop > fewest ? substeps - drop : fewest;
}

// The strain an edge left by `s.leftBy` sub-steps may have for the count to
// be lowered from s.substeps: kStrainLoweringMargin ε scaled by the h^2 law
// to the lowered count. 0 before the first step (nothing is calm).
SOAK_INLINE float strainCalmBound(StrainSubsteps s, float target, int fewest) {
  if (s.leftBy <= 0 || s.substeps <= 0) return 0.f;
  const float r = float(strainLoweredSubsteps(s.substeps, fewest)) / float(s.leftBy);
  if (strainProbing(s)) {
    const float asIs = kStrainProbeMargin * target, byLaw = kStrainProbeLawMargin * target * r * r;
    return asIs < byLaw ? asIs : byLaw;
  }
  return kStrainLoweringMargin * target * r * r;
}
// An edge's strain as the strain rule counts it: |l - l0| / l0, or with
// `stretchOnly` the stretch (l - l0) / l0.
SOAK_INLINE float edgeStrain(Vec3 a, Vec3 b, float rest, bool stretchOnly) {
  const float change = (length(a - b) - rest) / rest;
  return stretchOnly ? change : fabsf(change);
}
// 1 % of `edges`, rounded up: more edges than this past a bound put the
// 99th percentile past it.
SOAK_INLINE long long strainOnePercent(int edges) { return (static_cast<long long>(edges) + 99) / 100; }

struct SubstepClock;
// Writes to counts[0] the edges whose strain |l - l0| / l0 exceeds `target`
// and to counts[1] those exceeding strainCalmBound of the clock's strain
// state (device memory), without a wait. With `stretchOnly`
// (Simulation.clothStrainStretchOnly) the strain is the stretch
// max(0, l / l0 - 1): compressed edges, where fabric wrinkles finer than
// the mesh, do not count. `flags` and `scan` hold 2 n ints.
void measureClothStrain(Device d, ParticleView p, const int* vertexSlot, const ClothEdge* edges, const float* rest,
                        int n, float target, int fewest, bool stretchOnly, const SubstepClock* clock, int* flags,
                        int* scan, int* counts);

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

// How a step's count is chosen: `fewest` (Simulation.clothSubsteps) unless
// travel > 0 (Simulation.clothSubstepTravel): then from the largest travel
// up to `most`, and from the strain counts (where measured) up to
// `strainMost`, the larger of the two.
struct SubstepChoice {
  int fewest = 1;
  float travel = 0.f;
  int most = 1;
  int strainFirst = 0;  // the strain rule's count before its first measurement (0: fewest)
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

// The rule's state after a raise: no calm or steady spell, and a probe the
// raise undoes doubles the wait for the next.
SOAK_INLINE StrainSubsteps strainRaised(StrainSubsteps s) {
  s.calmSteps = 0;
  s.steadySteps = 0;
  if (s.probeAge >= 0) {
    s.steadyWait = s.steadyWait * 2 < kStrainMostSteadySteps ? s.steadyWait * 2 : kStrainMostSteadySteps;
    s.probeAge = -1;
  }
  return s;
}

// What the strain asks for next, from what it asked before and the counts:
// `above` edges past the target, `aboveCalm` past strainCalmBound.
// Before the first measurement (current.substeps 0) the count is `first`
// (0: fewest), within [fewest, most].
SOAK_INLINE StrainSubsteps substepsForStrain(StrainSubsteps current, int above, int aboveCalm, int edges, int fewest,
                                             int most, int first = 0) {
  const int top = fewest > most ? fewest : most;
  StrainSubsteps next = current;
  const int asked = current.substeps > 0 ? current.substeps : first;
  next.substeps = asked < fewest ? fewest : asked > top ? top : asked;
  const long long onePercent = strainOnePercent(edges);
  if (next.steadySteps < kStrainMostSteadySteps) ++next.steadySteps;
  if (next.probeAge >= 0 && ++next.probeAge > kStrainProbeSteps) {  // the probe's count held
    next.probeAge = -1;
    next.steadyWait = kStrainSteadySteps;
  }
  if (above > onePercent) {
    const int half = next.substeps / 2 > 1 ? next.substeps / 2 : 1;
    const long long wide = (static_cast<long long>(edges) * kStrainWidePercent + 99) / 100;
    const int raise = above > wide ? half : 1;
    next.substeps = next.substeps + raise < top ? next.substeps + raise : top;
    next = strainRaised(next);
  } else if (aboveCalm < onePercent && next.substeps > fewest) {
    if (++next.calmSteps >= kStrainCalmSteps) {
      if (strainProbing(current)) next.probeAge = 0;
      next.substeps = strainLoweredSubsteps(next.substeps, fewest);
      next.calmSteps = 0;
    }
  } else {
    next.calmSteps = 0;
  }
  return next;
}

}  // namespace soak
