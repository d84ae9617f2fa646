#include "Cloth/AdaptiveSubsteps.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

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
                        int n, float target, int* flags, int* scan, int* counts) {
  if (n == 0) return;
  const float quarter = 0.25f * target;
  forEach(d, n, SOAK_LAMBDA(int e) {
    const Vec3 a = p.position[vertexSlot[edges[e].a]].xyz();
    const Vec3 b = p.position[vertexSlot[edges[e].b]].xyz();
    const float strain = fabsf(length(a - b) - rest[e]) / rest[e];
    flags[e] = strain > target;
    flags[n + e] = strain > quarter;
  }, "cloth.substeps.strain");
  exclusiveScanAsync(d, flags, scan, 2 * n);
  forEach(d, 1, SOAK_LAMBDA(int) {
    counts[0] = scan[n];
    counts[1] = scan[2 * n - 1] + flags[2 * n - 1] - scan[n];
  }, "cloth.substeps.strain_counts");
}

StrainSubsteps substepsForStrain(StrainSubsteps current, int above, int aboveQuarter, int edges, int fewest,
                                 int most) {
  const int top = std::max(fewest, most);
  StrainSubsteps next = current;
  next.substeps = std::clamp(current.substeps, fewest, top);
  const long long onePercent = (std::int64_t(edges) + 99) / 100;  // edges past the 99th percentile
  if (above > onePercent) {
    next.substeps = std::min(top, next.substeps + std::max(1, next.substeps / 2));
    next.calmSteps = 0;
  } else if (aboveQuarter < onePercent) {
    if (++next.calmSteps >= kStrainCalmSteps) {
      next.substeps = std::max(fewest, next.substeps - 1);
      next.calmSteps = 0;
    }
  } else {
    next.calmSteps = 0;
  }
  return next;
}

int substepsForTravel(float perStep, float travel, int fewest, int most) {
  if (!std::isfinite(perStep)) return std::max(fewest, most);
  const double wanted = std::ceil(double(perStep) / double(travel));
  return int(std::clamp(wanted, double(fewest), double(std::max(fewest, most))));
}

}  // namespace soak
