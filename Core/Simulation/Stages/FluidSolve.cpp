// fluid.solve: the density constraints of PBF (Eqs. 1-4).
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runFluidSolve(CoreStageState&, Simulation& sim) {
  sim.fluid.solve(sim.particles, sim.fluidContext(), sim.sizeListsNow());
}

}  // namespace soak
