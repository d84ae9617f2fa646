// predict: v += dt g, x* = x + dt v (Algorithm 1, lines 2-3).
#include "Physics/Integrate.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runPredict(CoreStageState&, Simulation& sim) {
  predictPositions(sim.device(), sim.particles.view(), sim.settings.gravity, float(sim.settings.timeStep));
}

}  // namespace soak
