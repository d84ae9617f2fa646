#include "Cloth/AdaptiveSubsteps.h"

#include "Cloth/SubstepClock.h"

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"

namespace soak {

void measureClothTravel(Device d, ParticleView p, ClothView c, float dt, float* scratch, float* maxTravel) {
  forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
    const int slot = c.vertexSlot[v];
    scratch[v] = length(p.velocity[slot]) * dt / c.thickness[v];
  }, "cloth.substeps.travel");
  reduceMaxInto(d, scratch, c.vertexCount, maxTravel);
}

void measureClothStrain(Device d, ParticleView p, const int* vertexSlot, const ClothEdge* edges, const float* rest,
                        int n, float target, int fewest, bool stretchOnly, const SubstepClock* clock, int* flags,
                        int* scan, int* counts) {
  if (n == 0) return;
  forEach(d, n, SOAK_LAMBDA(int e) {
    const float calm = strainCalmBound(clock->strain, target, fewest);
    const float strain = edgeStrain(p.position[vertexSlot[edges[e].a]].xyz(), p.position[vertexSlot[edges[e].b]].xyz(),
                                    rest[e], stretchOnly);
    flags[e] = strain > target;
    flags[n + e] = strain > calm;
  }, "cloth.substeps.strain");
  exclusiveScanAsync(d, flags, scan, 2 * n);
  forEach(d, 1, SOAK_LAMBDA(int) {
    counts[0] = scan[n];
    counts[1] = scan[2 * n - 1] + flags[2 * n - 1] - scan[n];
  }, "cloth.substeps.strain_counts");
}

void chooseClothSubsteps(Device d, SubstepClock* clock, const float* maxTravel, const int* strainCounts,
                         SubstepChoice choice) {
  forEach(d, 1, SOAK_LAMBDA(int) {
    SubstepClock& k = *clock;
    int n = choice.fewest;
    if (choice.travel > 0.f) {
      n = substepsForTravel(*maxTravel, choice.travel, choice.fewest, choice.most);
      if (strainCounts) {
        k.strain = substepsForStrain(k.strain, strainCounts[0], strainCounts[1], choice.strainEdges, choice.fewest,
                                     choice.strainMost, choice.strainFirst);
        if (k.strain.substeps > n) n = k.strain.substeps;
      }
    }
    k.substep = 0;
    k.substeps = n;
    k.attempt = 0;
    k.redoPast = 0;
    k.strain.leftBy = n;
    k.contactSubsteps = choice.travel > 0.f && choice.contactsBySpeed
                            ? contactSubstepsForTravel(*maxTravel, choice.travel, n)
                            : n;
    k.taken += n;
  }, "cloth.substeps.choose");
}

}  // namespace soak
