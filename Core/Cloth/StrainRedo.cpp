#include "Cloth/StrainRedo.h"

#include <cmath>

#include "Backend/ForEach.h"
#include "Base/Atomic.h"

namespace soak {

void checkStrainRedo(Device d, ParticleView p, const int* vertexSlot, StrainRedoCheck check, SubstepClock* clock) {
  if (check.edgeCount == 0) return;
  forEach(d, check.edgeCount, SOAK_LAMBDA(int e) {
    if (clock->substep + 1 != clock->substeps) return;  // not the step's last sub-step
    const Vec3 a = p.predicted[vertexSlot[check.edges[e].a]].xyz();
    const Vec3 b = p.predicted[vertexSlot[check.edges[e].b]].xyz();
    const float change = length(a - b) - check.rest[e];
    if ((check.stretchOnly ? change : fabsf(change)) > check.bound * check.rest[e]) atomicAddInt(&clock->redoPast, 1);
  }, "cloth.substeps.redo_count");
  forEach(d, 1, SOAK_LAMBDA(int) {
    SubstepClock& k = *clock;
    if (k.substep + 1 != k.substeps) return;
    const long long onePercent = (static_cast<long long>(check.edgeCount) + 99) / 100;
    const int past = k.redoPast;
    k.redoPast = 0;
    if (past <= onePercent || k.attempt >= kStrainRedoAttempts || k.substeps >= check.most) return;
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
