// neighbours: the particles sorted into the grid; the cloth's slots, its own
// grid, and the cloth's boundary volumes for the fluid's density (Eq. 1).
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runNeighbours(CoreStageState&, Simulation& sim) {
  sim.grid.build(sim.particles, sim.maxSupportRadius());
  if (sim.cloth.empty()) return;
  sim.cloth.updateSlots(sim.particles.view());
  sim.cloth.buildGrid(sim.grid.view());
  sim.fluid.computeBoundaryVolumes(sim.particles.view(), sim.cloth.grid(), clothSlots(sim.cloth.view()));
}

}  // namespace soak
