// cloth.solve: the cloth's constraints, colliders and contact, in one or more
// sub-steps (Cloth/ClothStep.h).
#include "Physics/Integrate.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runClothSolve(CoreStageState& state, Simulation& sim) {
  if (sim.cloth.empty()) return;
  const SimulationSettings& set = sim.settings;
  state.cloth.run(sim.particles.view(), sim.cloth, sim.deviceColliders(), int(sim.colliders.size()),
                  {float(set.timeStep), set.gravity, set.clothSubsteps, set.clothSubstepTravel, set.clothMaxSubsteps,
                   set.clothContactsBySpeed, set.clothAccelerationLimit, set.clothStrainMaxSubsteps, set.clothStrainFirstSubsteps,
                   set.clothStrainTarget, set.clothStrainStretchOnly, set.clothStrainRedo, set.clothIterations,
                   {set.clothSpectralRadius, set.clothChebyshevDelay},
                   set.contactPasses, set.crossingGuardRounds, kCollisionRadiusScale, sim.sizeListsNow()});
}

}  // namespace soak
