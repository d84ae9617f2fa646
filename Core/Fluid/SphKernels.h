#pragma once
// SPH kernels of Position Based Fluids (Macklin & Mueller 2013), as the paper
// uses them (Section 5): Poly6 for densities, Spiky for gradients.
// Particles of different support radii interact through the symmetric
// h_ij = (h_i + h_j) / 2, so W_ij = W_ji and grad_i W_ij = -grad_j W_ij.
#include "Base/HostDevice.h"
#include "Base/Vec3.h"

namespace soak {

constexpr float kPi = 3.14159265358979f;

SOAK_INLINE float pairSupport(float hi, float hj) { return 0.5f * (hi + hj); }

// Poly6: W(r, h) = 315 / (64 pi h^9) (h^2 - r^2)^3 for r < h.
SOAK_INLINE float poly6(float r2, float h) {
  const float h2 = h * h;
  if (r2 >= h2) return 0.f;
  const float d = h2 - r2;
  const float h3 = h2 * h;
  return 315.f / (64.f * kPi * h3 * h3 * h3) * d * d * d;
}

// Spiky gradient with respect to x_i of W(x_i - x_j, h):
// -45 / (pi h^6) (h - r)^2 (x_i - x_j) / r for 0 < r < h.
SOAK_INLINE Vec3 spikyGradient(Vec3 xij, float r, float h) {
  if (r >= h || r <= 1e-9f) return Vec3(0.f, 0.f, 0.f);
  const float h3 = h * h * h;
  const float d = h - r;
  return xij * (-45.f / (kPi * h3 * h3) * d * d / r);
}

// W(r, h) / W(q h, h) for Poly6, r < h: ((h^2 - r^2) / (h^2 (1 - q^2)))^3,
// the normalisation cancelled (one division instead of three).
SOAK_INLINE float poly6Ratio(float r2, float h, float q) {
  const float h2 = h * h;
  const float ratio = (h2 - r2) / (h2 * (1.f - q * q));
  return ratio * ratio * ratio;
}

}  // namespace soak
