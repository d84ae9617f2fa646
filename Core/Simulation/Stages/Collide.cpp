// collide: the water's predicted positions out of the colliders. The cloth
// solve has projected the cloth's in each of its sub-steps, with the
// colliders' friction over the sub-step; projecting them again here, with
// friction over the whole step, would move them after the solve, unseen by
// its constraints and its strain rule (fig9b's landing with the default
// counts, CPU: 2.68 % p99 with, 1.58 % without; Doc/model.md, "Colliders
// after the cloth solve").
#include "Physics/Integrate.h"
#include "Simulation/Simulation.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

void runCollide(CoreStageState&, Simulation& sim) {
  projectColliders(sim.device(), sim.particles.view(), sim.deviceColliders(), int(sim.colliders.size()),
                   kCollisionRadiusScale, float(sim.settings.timeStep), /*clothFrictionScale=*/nullptr,
                   /*waterOnly=*/true);
}

}  // namespace soak
