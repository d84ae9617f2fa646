#pragma once
// Small formulas of the wetting model, shared by the stages.
#include <cmath>

#include "Base/HostDevice.h"
#include "Base/Vec3.h"
#include "Fluid/SphKernels.h"

namespace soak::wet {

// cos(theta) between x_ij = x_i - x_j and the gravity direction g (unit):
// +1 when i lies straight below j.
SOAK_INLINE float cosToGravity(Vec3 xij, float r, Vec3 g) { return r > 0.f ? dot(xij, g) / r : 0.f; }

// The gravity term 1 + eta cos(theta_ij) of Eq. 11 and Eq. 12.
SOAK_INLINE float gravityTerm(float eta, float cosTheta) { return 1.f + eta * cosTheta; }

// Laplacian of the viscosity kernel, 45 / (pi h^6) (h - r): positive on the
// whole support, so that Eq. 12 weights every neighbour positively (the
// Poly6 Laplacian changes sign; Doc/model.md).
SOAK_INLINE float laplacianWeight(float r, float h) {
  if (r >= h) return 0.f;
  const float h2 = h * h;
  return 45.f / (kPi * h2 * h2 * h2) * (h - r);
}

// Saturation (Eq. 10) of held water mass m in volume V.
SOAK_INLINE float saturationOf(float c, float held, float volume) { return volume > 0.f ? c * held / volume : 0.f; }

// Eq. 22 per vertex: 1 - max(0, S - S^T) / (S^MAX - S^T); a triangle's
// kappa_couple is the mean of its three vertices' values, which is Eq. 22.
SOAK_INLINE float couplingStiffnessOf(float S, float sT, float sMax) {
  const float k = 1.f - maxf(S - sT, 0.f) / (sMax - sT);
  return minf(maxf(k, 0.f), 1.f);
}

// Eq. 20's magnitude, clamped at zero.
SOAK_INLINE float stickingMagnitude(float Si, float Sj, float sT, float kappaAd, float etaAd) {
  return maxf(etaAd - kappaAd * fabsf((Si - sT) * (Sj - sT)), 0.f);
}

}  // namespace soak::wet
