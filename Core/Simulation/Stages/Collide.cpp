// collide: every particle's predicted position out of the colliders.
#include "Cloth/VertexFields.h"
#include "Physics/Integrate.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runCollide(CoreStageState&, Simulation& sim) {
  projectColliders(sim.device(), sim.particles.view(), sim.deviceColliders(), int(sim.colliders.size()),
                   kCollisionRadiusScale, float(sim.settings.timeStep), sim.vertexFields.find(field::kFrictionScale));
}

}  // namespace soak
