#pragma once
// Density that a collider's surface adds to a water particle near it.
//
// Colliders have no particles, so a water particle at a wall would see half
// a neighbourhood and the column above would squeeze it into the wall. We
// add the density of a virtual water lattice filling the collider (layers
// r0 apart, the first r0/2 beyond the surface, continuous within each
// layer): rho_wall(d), with d the particle's distance to the surface. A
// particle of a rest lattice then sees the rest lattice's density at a wall
// too, and the gradient of rho_wall pushes it away from the wall. Tabulated
// once (Doc/model.md, "Walls").
#include "Base/HostDevice.h"
#include "Physics/Collider.h"

namespace soak {

struct WallDensityTable {
  static constexpr int kSamples = 48;
  float rho[kSamples];    // kg/m^3 at d = i * step
  float slope[kSamples];  // d rho / d d (negative)
  float step = 1.f;
  float range = 0.f;      // beyond this the wall adds nothing
};

WallDensityTable makeWallDensityTable(float spacing, float supportRadius, float particleMass);

SOAK_INLINE float wallDensityAt(const WallDensityTable& t, float d, float& slope) {
  if (d >= t.range) {
    slope = 0.f;
    return 0.f;
  }
  float u = maxf(d, 0.f) / t.step;
  int i = int(u);
  if (i >= WallDensityTable::kSamples - 1) i = WallDensityTable::kSamples - 2;
  const float a = u - float(i);
  slope = t.slope[i] * (1.f - a) + t.slope[i + 1] * a;
  return t.rho[i] * (1.f - a) + t.rho[i + 1] * a;
}

// Sum of the wall densities of all colliders at point x (with the gradient
// with respect to x). Each collider counts its nearest surface only, so the
// region behind two faces of a container's edge is not counted twice.
SOAK_INLINE float collidersDensity(const WallDensityTable& t, const Collider* colliders, int count, Vec3 x,
                                   Vec3& gradient) {
  float rho = 0.f;
  gradient = Vec3(0.f, 0.f, 0.f);
  for (int c = 0; c < count; ++c) {
    const Collider& col = colliders[c];
    Vec3 n;
    const float d = colliderDistance(col, x, n);
    float s;
    rho += wallDensityAt(t, d, s);
    gradient += n * s;
  }
  return rho;
}

}  // namespace soak
