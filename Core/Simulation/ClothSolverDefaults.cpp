#include "Simulation/ClothSolverDefaults.h"

namespace soak {

void resolveClothSolverCounts(SimulationSettings& s, const ClothModelsUsed& used) {
  const bool pbdCounts = used.pbd && !used.jacobiOrXpbd;
  if (s.clothSubsteps <= 0) s.clothSubsteps = pbdCounts ? kPbdSubsteps : kChebyshevSubsteps;
  if (s.clothIterations <= 0) s.clothIterations = pbdCounts ? kPbdIterations : kChebyshevIterations;
  // pbd's stiffness is set per iteration for a fixed count: no sub-steps from the speed.
  if (s.clothSubstepTravel < 0.f) s.clothSubstepTravel = used.pbd ? 0.f : kChebyshevTravel;
}

}  // namespace soak
