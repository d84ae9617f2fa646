#include "Cloth/StrainRedo.h"

#include "Backend/ForEach.h"
#include "Base/Atomic.h"

namespace soak {

void checkStrainRedo(Device d, ParticleView p, const int* vertexSlot, StrainRedoCheck check, SubstepClock* clock) {
  if (check.edgeCount == 0) return;
  forEach(d, check.edgeCount, SOAK_LAMBDA(int e) {
    if (clock->substep + 1 != clock->substeps) return;  // not the step's last sub-step
    const ClothEdge edge = check.edges[e];
    if (edgeStrain(p.predicted[vertexSlot[edge.a]].xyz(), p.predicted[vertexSlot[edge.b]].xyz(), check.rest[e],
                   check.stretchOnly) > check.bound)
      atomicAddInt(&clock->redoPast, 1);
  }, "cloth.substeps.redo_count");
  forEach(d, 1, SOAK_LAMBDA(int) {
    SubstepClock& k = *clock;
    if (k.substep + 1 != k.substeps) return;
    const int past = k.redoPast;
    k.redoPast = 0;
    if (past <= strainOnePercent(check.edgeCount) || k.attempt >= kStrainRedoAttempts || k.substeps >= check.most) return;
    const int before = k.substeps, n = strainRedoSubsteps(before, check.most);
    ++k.attempt;
    k.taken += n;
    k.substeps = n;
    k.substep = -1;  // the loop's advance makes it 0: the step's sub-steps again
    k.strain = strainRedone(k.strain, n);
    if (k.contactSubsteps >= before) k.contactSubsteps = n;  // contacts in every sub-step stay so
  }, "cloth.substeps.redo");
}

}  // namespace soak
