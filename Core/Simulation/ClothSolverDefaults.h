#pragma once
// The cloth solver's counts when a scene leaves them to the solver
// (Simulation.clothIterations = 0, clothSubsteps = 0, clothSubstepTravel < 0,
// the defaults): chosen from the cloth models the scene uses, so that a
// <Cloth> that names nothing holds its shape (Doc/model.md, "Cloth solvers").
//
// - chebyshev and xpbd cloth: kChebyshevSubsteps sub-steps of
//   kChebyshevIterations Jacobi iterations, more sub-steps when the cloth
//   moves fast (travel kChebyshevTravel of its thickness per sub-step). On the
//   README's example (2 s, CPU) this leaves 0.05 % mean / 0.63 % p99 edge
//   strain in its worst frame where the paper's PBD at 1 x 8 leaves 0.74 % /
//   12.7 % (with the Chebyshev weights at rho 0.6 from the first iteration:
//   0.09 % / 1.4 %, and 2 x 25, as many phases, 2.9 % p99; Doc/performance.md,
//   "Default cloth solver").
//   With the sub-steps left to the solver, it also raises them while the
//   strain its solve leaves passes kChebyshevStrainTarget at the 99th
//   percentile (Cloth/AdaptiveSubsteps.h), up to kStrainSubstepsFactor
//   times its first count, 32 (at rho 0.6: a sheet hung from one diagonal
//   then left 2.85 % p99 where a fixed 4 x 12 left 3.6 %), and lowers
//   them where the strain stays low down to kChebyshevFewestSubsteps: the
//   rule starts at 4, so a sheet's
//   first fall is solved as finely as a fixed 4 x 12 (from 2, fig7's and
//   fig3a's worst frames, in their first 0.15 s, were 2.92 % and 2.78 %
//   p99 against 2.53 % and 2.41 %), and a sheet that hangs quietly comes
//   down to 2 x 12, where fig1's and fig5b's hung sheets leave 1.0-1.1 %
//   p99 (CPU, 1.5 s; 0.5-0.6 % at 4), at the cost of the scenes' own 2 x 12.
//   A scene that names its sub-steps keeps them (the figure scenes, whose
//   counts are tuned and timed).
//   With the strain rule, a vertex also leaves a step at most
//   kChebyshevAccelerationLimit x dt / 2 faster than its mean motion
//   (Simulation.clothAccelerationLimit, Cloth/ClothSolve.h): the counts
//   the rule and the speed choose reach 32, where layers caught through
//   each other set fig6b's sheet flailing; under a scene's own counts the
//   limit is off unless given (at 8 x 12 it changed where a folded sheet
//   at rest on the floor settles: Doc/model.md, "The end velocity's limit").
// - pbd only: the paper's 1 x 8, sub-steps fixed (its stiffness is per
//   iteration, Eq. 5).
// - both kinds in one scene: kChebyshevSubsteps x kChebyshevIterations,
//   sub-steps fixed.
// Counts a scene gives are kept as given.
#include "Simulation/Settings.h"

namespace soak {

constexpr int kChebyshevSubsteps = 4;          // fixed, or the strain rule's first count
constexpr int kChebyshevFewestSubsteps = 2;    // the fewest the strain rule lowers to
constexpr int kChebyshevIterations = 12;
constexpr float kChebyshevTravel = 0.5f;
constexpr float kChebyshevStrainTarget = 0.02f;
constexpr float kChebyshevAccelerationLimit = 200.f;  // m/s^2
constexpr int kPbdSubsteps = 1;
constexpr int kPbdIterations = 8;

// Which cloth models a scene uses (each <Cloth> notes its own while the
// settings are read, so the result does not depend on the elements' order).
struct ClothModelsUsed {
  bool pbd = false;
  bool jacobiOrXpbd = false;
};

// Replaces the "solver's choice" values of `s` by the counts above.
void resolveClothSolverCounts(SimulationSettings& s, const ClothModelsUsed& used);

}  // namespace soak
