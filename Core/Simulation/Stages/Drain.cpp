// drain: water outside the domain, in a sink or wholly absorbed is marked
// removed; on a maintenance step the removed slots are compacted away.
#include "Physics/Drain.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runDrain(CoreStageState& state, Simulation& sim) {
  markDrainedWater(sim.device(), sim.particles.view(),
                   {sim.settings.domainMin, sim.settings.domainMax, state.sinkCorners.data(), int(sim.sinks.size())});
  if (sim.maintenanceStep()) sim.compact();
}

}  // namespace soak
