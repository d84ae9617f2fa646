#include "Simulation/ClothSolverDefaults.h"

namespace soak {

void resolveClothSolverCounts(SimulationSettings& s, const ClothModelsUsed& used) {
  const bool pbdCounts = used.pbd && !used.jacobiOrXpbd;
  const bool solversSubsteps = s.clothSubsteps <= 0;
  if (s.clothStrainTarget < 0.f) s.clothStrainTarget = solversSubsteps && !used.pbd ? kChebyshevStrainTarget : 0.f;
  const bool strainRule = solversSubsteps && s.clothStrainTarget > 0.f && s.clothSubstepTravel != 0.f;
  if (s.clothAccelerationLimit < 0.f) s.clothAccelerationLimit = strainRule ? kChebyshevAccelerationLimit : 0.f;
  if (strainRule) {
    // The rule starts at the chebyshev count and may lower it to the fewest.
    s.clothSubsteps = kChebyshevFewestSubsteps;
    s.clothStrainFirstSubsteps = kChebyshevSubsteps;
  } else if (solversSubsteps) {
    s.clothSubsteps = pbdCounts ? kPbdSubsteps : kChebyshevSubsteps;
  }
  if (s.clothIterations <= 0) s.clothIterations = pbdCounts ? kPbdIterations : kChebyshevIterations;
  // pbd's stiffness is set per iteration for a fixed count: no sub-steps from the speed.
  if (s.clothSubstepTravel < 0.f) s.clothSubstepTravel = used.pbd ? 0.f : kChebyshevTravel;
}

}  // namespace soak
