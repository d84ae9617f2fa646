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

// The kernels' normalisations: 315 / (64 pi h^9) of Poly6, -45 / (pi h^6)
// of the Spiky gradient.
SOAK_INLINE float poly6Factor(float h) {
  const float h3 = h * h * h;
  return 315.f / (64.f * kPi * h3 * h3 * h3);
}
SOAK_INLINE float spikyFactor(float h) {
  const float h3 = h * h * h;
  return -45.f / (kPi * h3 * h3);
}

// Poly6: W(r, h) = 315 / (64 pi h^9) (h^2 - r^2)^3 for r < h.
SOAK_INLINE float poly6(float r2, float h) {
  const float h2 = h * h;
  if (r2 >= h2) return 0.f;
  const float d = h2 - r2;
  return poly6Factor(h) * d * d * d;
}

// Spiky gradient with respect to x_i of W(x_i - x_j, h):
// -45 / (pi h^6) (h - r)^2 (x_i - x_j) / r for 0 < r < h.
SOAK_INLINE Vec3 spikyGradient(Vec3 xij, float r, float h) {
  if (r >= h || r <= 1e-9f) return Vec3(0.f, 0.f, 0.f);
  const float d = h - r;
  return xij * (spikyFactor(h) * d * d / r);
}

// 1 / sqrt(x) for x > 0: the hardware's reciprocal square root on the GPU
// (one instruction instead of a rounded square root and a division).
SOAK_INLINE float reciprocalSqrt(float x) {
#if defined(__CUDA_ARCH__)
  return rsqrtf(x);
#else
  return 1.f / sqrtf(x);
#endif
}

// The kernels for one support radius h, for passes over pairs that nearly
// all share one h (the particles of one kind): a pass keeps the last pair's
// factors and computes them again only for a pair with another h, so each
// pair costs multiplications and a reciprocal square root instead of a
// square root and three divisions (the passes are bound by their
// instructions, not their loads: Doc/performance.md, "What limits the step").
struct SphPairFactors {
  float h = -1.f, h2 = 0.f;
  float poly6 = 0.f;  // poly6Factor(h)
  float spiky = 0.f;  // spikyFactor(h)
  float ratio = 0.f;  // 1 / (h^2 (1 - q^2)), for poly6RatioAt
  SOAK_INLINE void setFor(float support, float q) {
    h = support;
    h2 = support * support;
    poly6 = poly6Factor(support);
    spiky = spikyFactor(support);
    ratio = 1.f / (h2 * (1.f - q * q));
  }
  // Poly6 at r2 < h2.
  SOAK_INLINE float poly6At(float r2) const {
    const float d = h2 - r2;
    return poly6 * d * d * d;
  }
  // W(r, h) / W(q h, h) for Poly6 at r2 < h2, the normalisation cancelled:
  // ((h^2 - r^2) / (h^2 (1 - q^2)))^3.
  SOAK_INLINE float poly6RatioAt(float r2) const {
    const float x = (h2 - r2) * ratio;
    return x * x * x;
  }
  // The Spiky gradient for xij with r2 = |xij|^2 < h2 (0 at r = 0).
  SOAK_INLINE Vec3 spikyGradientAt(Vec3 xij, float r2) const {
    if (r2 <= 1e-18f) return Vec3(0.f, 0.f, 0.f);
    const float invR = reciprocalSqrt(r2);
    const float d = h - r2 * invR;
    return xij * (spiky * d * d * invR);
  }
};

}  // namespace soak
