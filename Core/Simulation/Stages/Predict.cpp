// predict: v += dt g, x* = x + dt v (Algorithm 1, lines 2-3); with sub-steps from
// the cloth's speed, also queues the measurement of the cloth's travel.
#include "Physics/Integrate.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runPredict(CoreStageState& state, Simulation& sim) {
  predictPositions(sim.device(), sim.particles.view(), sim.settings.gravity, float(sim.settings.timeStep));
  // The cloth's travel this step decides its sub-steps (Cloth/AdaptiveSubsteps.h).
  if (!sim.cloth.empty() && sim.settings.clothSubstepTravel > 0.f)
    state.cloth.measureTravel(sim.particles.view(), sim.cloth, float(sim.settings.timeStep),
                              sim.settings.clothStrainTarget, sim.settings.clothSubsteps,
                              sim.settings.clothStrainStretchOnly);
}

}  // namespace soak
