// coupling: water kept on its side of the cloth's triangles (Eq. 21), with
// the per-vertex coupling stiffness a plugin may publish (Eq. 22).
#include "Cloth/VertexFields.h"
#include "Coupling/TriangleCoupling.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runCoupling(CoreStageState& state, Simulation& sim) {
  if (sim.cloth.empty()) return;
  state.couplingMoved.resize(std::size_t(sim.particles.count()));
  projectWaterOutOfCloth(sim.device(), sim.particles.view(), sim.cloth.grid(), sim.cloth.view(),
                         sim.vertexFields.find(field::kCouplingStiffness), sim.settings.couplingPasses,
                         state.couplingMoved.data());
}

}  // namespace soak
