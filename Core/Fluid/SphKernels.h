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

// The kernels' factors that depend on h alone, computed as poly6() and
// spikyGradient() compute them, so that the variants below give the same
// bits. The fluid passes evaluate the kernels for every pair, and most pairs
// share the water's h: their factors are computed once per particle instead
// of with two or three divisions per pair.
struct KernelFactors {
  float h = 0.f;
  float poly6 = 0.f;   // 315 / (64 pi h^9)
  float spiky = 0.f;   // -45 / (pi h^6)
  float scorr = 0.f;   // h^2 (1 - q^2), for poly6Ratio
};

SOAK_INLINE KernelFactors kernelFactors(float h, float q = 0.f) {
  KernelFactors k;
  k.h = h;
  const float h2 = h * h, h3 = h2 * h;
  k.poly6 = 315.f / (64.f * kPi * h3 * h3 * h3);
  const float s3 = h * h * h;
  k.spiky = -45.f / (kPi * s3 * s3);
  k.scorr = h2 * (1.f - q * q);
  return k;
}

// Factors for h: `common`'s when h is its radius, else computed.
SOAK_INLINE KernelFactors kernelFactorsFor(float h, const KernelFactors& common, float q = 0.f) {
  return h == common.h ? common : kernelFactors(h, q);
}

SOAK_INLINE float poly6(float r2, const KernelFactors& k) {
  const float h2 = k.h * k.h;
  if (r2 >= h2) return 0.f;
  const float d = h2 - r2;
  return k.poly6 * d * d * d;
}

SOAK_INLINE Vec3 spikyGradient(Vec3 xij, float r, const KernelFactors& k) {
  if (r >= k.h || r <= 1e-9f) return Vec3(0.f, 0.f, 0.f);
  const float d = k.h - r;
  return xij * (k.spiky * d * d / r);
}

// W(r, h) / W(q h, h) for Poly6, r < h: ((h^2 - r^2) / (h^2 (1 - q^2)))^3,
// the normalisation cancelled (k from kernelFactors(h, q)).
SOAK_INLINE float poly6Ratio(float r2, const KernelFactors& k) {
  const float ratio = (k.h * k.h - r2) / k.scorr;
  return ratio * ratio * ratio;
}

}  // namespace soak
