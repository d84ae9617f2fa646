// finalize: v = (x* - x) / dt (with the cloth sub-steps' velocity fix), x = x*;
// then the fluid's XSPH viscosity and vorticity confinement.
#include "Physics/Integrate.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runFinalize(CoreStageState& state, Simulation& sim) {
  updateVelocities(sim.device(), sim.particles.view(), float(sim.settings.timeStep),
                   sim.cloth.empty() ? nullptr : state.cloth.velocityFix());
  sim.fluid.applyViscosity(sim.particles.view(), sim.fluidContext());
}

}  // namespace soak
